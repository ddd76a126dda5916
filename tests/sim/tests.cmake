# The simulated drive at the service level (no codec): each links drivedesk_sim only.
drivedesk_add_test(NAME tst_simdatabase LABELS unit SOURCES sim/tst_simdatabase.cpp sim/SimRequests.h LIBS drivedesk_sim)
drivedesk_add_test(NAME tst_simvalues LABELS unit SOURCES sim/tst_simvalues.cpp sim/SimRequests.h LIBS drivedesk_sim)
drivedesk_add_test(NAME tst_simmetadata LABELS unit SOURCES sim/tst_simmetadata.cpp sim/SimRequests.h LIBS drivedesk_sim)
drivedesk_add_test(NAME tst_simlive LABELS unit SOURCES sim/tst_simlive.cpp sim/SimRequests.h LIBS drivedesk_sim)
# Drives that differ: user settings by address, another kind, no identification.
drivedesk_add_test(NAME tst_simkinds LABELS unit SOURCES sim/tst_simkinds.cpp sim/SimRequests.h LIBS drivedesk_sim)
