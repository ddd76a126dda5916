# The compare window: files, defaults, sets, values written into a file and the selection for the
# drive (offscreen, against the simulated drive).
drivedesk_add_test(NAME tst_comparewindow LABELS gui
    SOURCES gui/tst_comparewindow.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui)
