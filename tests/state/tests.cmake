# core/state: a drive's state held once, the one rule for what may be written.
drivedesk_add_test(NAME tst_drivestate LABELS unit
    SOURCES state/tst_drivestate.cpp parameters/EditorSampleDrive.h
    LIBS drivedesk_state drivedesk_translations)
