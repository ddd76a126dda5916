# The scope's chart: decimated drawing, roll mode, zoom and keys, cursors, axes, export
# (offscreen).
drivedesk_add_test(NAME tst_scopechart LABELS gui
    SOURCES gui/tst_scopechart.cpp LIBS drivedesk_ui)
