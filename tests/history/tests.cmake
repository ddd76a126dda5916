# A plant's backups as revisions of a git repository: commits, history and revisions read back,
# in repositories of their own with git's user configuration kept out.
drivedesk_add_test(NAME tst_backuphistory LABELS unit
    SOURCES history/tst_backuphistory.cpp history/GitTestHome.h parameters/EditorSampleDrive.h
    LIBS drivedesk_history)
