# Editing: write, read-back, undo, copy, refresh, polling, the password level and their dialogs,
# against the simulated drive (offscreen).
drivedesk_add_test(NAME tst_editcontroller LABELS gui
    SOURCES gui/tst_editcontroller.cpp gui/tst_editsupport.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_polling LABELS gui
    SOURCES gui/tst_polling.cpp gui/tst_editsupport.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_access LABELS gui
    SOURCES gui/tst_access.cpp gui/tst_editsupport.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_editdialogs LABELS gui
    SOURCES gui/tst_editdialogs.cpp LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_windowdownload LABELS gui
    SOURCES gui/tst_windowdownload.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui)
