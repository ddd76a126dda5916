# A machine of many drives: the plant file.
drivedesk_add_test(NAME tst_plantfile LABELS unit
    SOURCES plant/tst_plantfile.cpp LIBS drivedesk_plant)
# The job that works through every drive of a plant, against simulated drives in process.
drivedesk_add_test(NAME tst_plantrun LABELS integration
    SOURCES plant/tst_plantrun.cpp LIBS drivedesk_plant drivedesk_bus)
# A link cut part-way through a plant's backup and download, against drives behind TCP ports:
# the other links go through and what is said of each drive is true of it, read again.
drivedesk_add_test(NAME tst_plantcut LABELS integration
    SOURCES plant/tst_plantcut.cpp LIBS drivedesk_plant drivedesk_bus)
# What is known of each drive of a plant, fed by real runs against simulated drives: who
# answers, identification, results, a link's state; another plant starts clean.
drivedesk_add_test(NAME tst_plantstate LABELS integration
    SOURCES plant/tst_plantstate.cpp LIBS drivedesk_plant drivedesk_bus)
