# A machine of many drives: the plant file.
drivedesk_add_test(NAME tst_plantfile LABELS unit
    SOURCES plant/tst_plantfile.cpp LIBS drivedesk_plant)
