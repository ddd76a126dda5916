# core/scope: the clock and the sample store; each links drivedesk_scope only.
drivedesk_add_test(NAME tst_scopeclock LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopeclock.cpp LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_samplestore LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_samplestore.cpp LIBS drivedesk_scope)
