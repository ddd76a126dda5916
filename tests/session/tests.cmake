# core/session: polling and the jobs of many requests, against the simulated drive through a
# real client.
drivedesk_add_test(NAME tst_sessionjobs LABELS unit TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_sessionjobs.cpp
    LIBS drivedesk_session drivedesk_bus)
