# The shell: the main window, its dialogs and the start-up options (offscreen, against the
# simulated drive).
drivedesk_add_test(NAME tst_mainwindow LABELS gui
    SOURCES gui/tst_mainwindow.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_mainwindow_edit LABELS gui
    SOURCES gui/tst_mainwindow_edit.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_mainwindow_dialogs LABELS gui
    SOURCES gui/tst_mainwindow_dialogs.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_finddrives LABELS gui
    SOURCES gui/tst_finddrives.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_offlineediting LABELS gui
    SOURCES gui/tst_offlineediting.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_savedrive LABELS gui
    SOURCES gui/tst_savedrive.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui)
# The journal view: filters, search, pages, a write appearing and its revert; the tooltip.
drivedesk_add_test(NAME tst_journalview LABELS gui
    SOURCES gui/tst_journalview.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui)
