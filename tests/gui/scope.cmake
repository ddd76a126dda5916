# The scope's chart: decimated drawing, roll mode, zoom and keys, cursors, axes, export
# (offscreen).
drivedesk_add_test(NAME tst_scopechart LABELS gui
    SOURCES gui/tst_scopechart.cpp LIBS drivedesk_ui)
# The chart's graphs drawn their own way on screen, checked against QCustomPlot's drawing of
# the same points; their legend entries.
drivedesk_add_test(NAME tst_scopegraph LABELS gui
    SOURCES gui/tst_scopegraph.cpp LIBS drivedesk_ui)
# The scope dock in the window: channels chosen in the panel and read back, recording, cursors,
# CSV of all and of the visible range, a recording file viewed with no drive, remembered settings.
drivedesk_add_test(NAME tst_scopedock LABELS gui
    SOURCES gui/tst_scopedock.cpp gui/tst_mainwindow_support.h gui/tst_scopesupport.h
    LIBS drivedesk_ui drivedesk_translations)
# Reading a recording in the dock (no drive): the measurements between the cursors.
drivedesk_add_test(NAME tst_scopeanalysis LABELS gui
    SOURCES gui/tst_scopeanalysis.cpp gui/tst_mainwindow_support.h gui/tst_scopesupport.h
    LIBS drivedesk_ui drivedesk_translations)
# Scope presets in the dock: a set-up saved and loaded back, a source the drive lacks said, a
# preset kept beside the plant open.
drivedesk_add_test(NAME tst_scopepresets LABELS gui
    SOURCES gui/tst_scopepresets.cpp gui/tst_mainwindow_support.h gui/tst_scopesupport.h
    LIBS drivedesk_ui drivedesk_translations)
# A math trace drawn from its min/max levels: the points a scan of its values gives.
drivedesk_add_test(NAME tst_scopemathtraces LABELS gui
    SOURCES gui/tst_scopemathtraces.cpp LIBS drivedesk_ui)
# The spectrum window beside a chart: a recording of a known sine; its peak over the view,
# between the cursors, and of a math channel; too few samples.
drivedesk_add_test(NAME tst_scopespectrumview LABELS gui
    SOURCES gui/tst_scopespectrumview.cpp LIBS drivedesk_ui drivedesk_translations)
# A second recording overlaid in the dock (no drive): aligned at the trigger or the start,
# named in the legend, read by the cursors, kept when the recording shown is replaced.
drivedesk_add_test(NAME tst_scopeoverlayview LABELS gui
    SOURCES gui/tst_scopeoverlayview.cpp gui/tst_mainwindow_support.h gui/tst_scopesupport.h
    LIBS drivedesk_ui drivedesk_translations)
# A run of the simulated drive read with an earlier run overlaid, a math channel, the cursors
# and the measurements, all at once; DRIVEDESK_SCOPE_SCREENSHOT=FILE saves docs/scope.png.
drivedesk_add_test(NAME tst_scopereading LABELS gui
    SOURCES gui/tst_scopereading.cpp gui/tst_mainwindow_support.h gui/tst_scopesupport.h
    LIBS drivedesk_ui drivedesk_translations)
