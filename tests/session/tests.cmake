# core/session: polling and the jobs of many requests, against the simulated drive through a
# real client.
drivedesk_add_test(NAME tst_sessionjobs LABELS unit TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_sessionjobs.cpp
    LIBS drivedesk_session drivedesk_bus)

# Parameter file downloads: the plan (flags, sets, checks, order) and the report, against the
# simulated drive, interrupted by the user and by a lost link.
drivedesk_add_test(NAME tst_download LABELS integration TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_download.cpp
    LIBS drivedesk_session drivedesk_bus)
