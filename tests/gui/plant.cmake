# The plant view: find, back up, verify and download every drive of a plant, a drive opened in
# the editor and two compared (offscreen, against simulated drives behind TCP ports).
drivedesk_add_test(NAME tst_plantview LABELS gui integration
    SOURCES gui/tst_plantview.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui
    drivedesk_translations)
