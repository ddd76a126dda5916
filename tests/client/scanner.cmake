# The drive scan against a hand-made drive behind a test RequestSink.
drivedesk_add_test(NAME tst_drivescanner LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_drivescanner.cpp LIBS drivedesk_client)
