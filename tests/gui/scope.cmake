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
# Scope presets in the dock: a set-up saved and loaded back, a source the drive lacks said, a
# preset kept beside the plant open.
drivedesk_add_test(NAME tst_scopepresets LABELS gui
    SOURCES gui/tst_scopepresets.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui
    drivedesk_translations)
