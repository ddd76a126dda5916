# The scope's chart: decimated drawing, roll mode, zoom and keys, cursors, axes, export
# (offscreen).
drivedesk_add_test(NAME tst_scopechart LABELS gui
    SOURCES gui/tst_scopechart.cpp LIBS drivedesk_ui)
# The scope dock in the window: channels chosen in the panel and read back, recording, cursors,
# CSV of all and of the visible range, a recording file viewed with no drive, remembered settings.
drivedesk_add_test(NAME tst_scopedock LABELS gui
    SOURCES gui/tst_scopedock.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui
    drivedesk_translations)
# Reading a recording in the dock (no drive): the measurements between the cursors.
drivedesk_add_test(NAME tst_scopeanalysis LABELS gui
    SOURCES gui/tst_scopeanalysis.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui
    drivedesk_translations)
# A second recording overlaid in the dock (no drive): aligned at the trigger or the start,
# named in the legend, read by the cursors, kept when the recording shown is replaced.
drivedesk_add_test(NAME tst_scopeoverlayview LABELS gui
    SOURCES gui/tst_scopeoverlayview.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui
    drivedesk_translations)
