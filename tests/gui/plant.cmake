# The plant view: find, back up, verify and download every drive of a plant, a drive opened in
# the editor and two compared (offscreen, against simulated drives behind TCP ports).
drivedesk_add_test(NAME tst_plantview LABELS gui integration
    SOURCES gui/tst_plantview.cpp gui/tst_mainwindow_support.h gui/tst_plantsupport.h
    LIBS drivedesk_ui drivedesk_translations)
# The plant view's History: backups committed, the revisions and their changes, two compared side
# by side, one restored through Download All's last look (offscreen, git in temporary folders).
drivedesk_add_test(NAME tst_planthistory LABELS gui integration
    SOURCES gui/tst_planthistory.cpp gui/tst_mainwindow_support.h gui/tst_plantsupport.h
    history/GitTestHome.h LIBS drivedesk_ui)
