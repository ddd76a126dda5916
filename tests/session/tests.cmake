# core/session: polling and the jobs of many requests, against the simulated drive through a
# real client.
drivedesk_add_test(NAME tst_sessionjobs LABELS unit TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_sessionjobs.cpp
    LIBS drivedesk_state drivedesk_bus)

# One change written and read back, against a sink the test answers in any order: when a
# read-back sent before its write's answer counts.
drivedesk_add_test(NAME tst_valuechange LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_valuechange.cpp
    LIBS drivedesk_session)

# Parameter file downloads: the plan (flags, sets, checks, order) and the report, against the
# simulated drive, interrupted by the user and by a lost link.
drivedesk_add_test(NAME tst_download LABELS integration TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_download.cpp
    LIBS drivedesk_session drivedesk_bus)
# A write whose answer is lost on the line, through a proxy in front of the simulated drive.
drivedesk_add_test(NAME tst_lostanswers LABELS integration TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_lostanswers.cpp
        ${CMAKE_CURRENT_LIST_DIR}/../client/SpoilingProxy.h
    LIBS drivedesk_state drivedesk_bus)

# Scope recording: channels assigned through the edit path (journaled, shown in the state) and
# read back, samples in order with the drive's values, the rate limit, a lost link and a silent
# drive, over HSP5 and DIN66019II.
drivedesk_add_test(NAME tst_scoperecording LABELS integration TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scoperecording.cpp
    LIBS drivedesk_state drivedesk_bus)

# Upload (drive to parameter file): a whole read equals the drive; a refused value, a drive gone
# silent or a cancel is refused, names what is missing and saves nothing.
drivedesk_add_test(NAME tst_upload LABELS integration TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_upload.cpp
    LIBS drivedesk_session drivedesk_bus)
