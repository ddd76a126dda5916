# The client: reply texts and checks (unit), and the real client against the simulated drive
# in process, over TCP and over pseudo-terminals (integration).
drivedesk_add_test(NAME tst_reply LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_reply.cpp LIBS drivedesk_client drivedesk_translations)
drivedesk_add_test(NAME tst_replycheck LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_replycheck.cpp LIBS drivedesk_client)
drivedesk_add_test(NAME tst_whenfinished LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_whenfinished.cpp LIBS drivedesk_client)

foreach(name clientservices clientdin clientpipeline clientfaults clienttransports clientscan clientunplug
        clientseedonly clientcache clientstall)
    drivedesk_add_test(NAME tst_${name} LABELS unit integration TIMEOUT 300
        SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_${name}.cpp ${CMAKE_CURRENT_LIST_DIR}/ClientTestSupport.h
        LIBS drivedesk_client drivedesk_bus drivedesk_translations)
endforeach()

drivedesk_add_test(NAME tst_baudratesearch LABELS unit integration TIMEOUT 120
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_baudratesearch.cpp ${CMAKE_CURRENT_LIST_DIR}/ClientTestSupport.h
    LIBS drivedesk_client drivedesk_bus drivedesk_translations)
drivedesk_add_test(NAME tst_clientsilence LABELS unit integration TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_clientsilence.cpp ${CMAKE_CURRENT_LIST_DIR}/ClientTestSupport.h
    LIBS drivedesk_client drivedesk_bus drivedesk_session drivedesk_translations)
drivedesk_add_test(NAME tst_clientgarbage LABELS unit integration TIMEOUT 300
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_clientgarbage.cpp ${CMAKE_CURRENT_LIST_DIR}/ClientTestSupport.h
        ${CMAKE_CURRENT_LIST_DIR}/SpoilingProxy.h
    LIBS drivedesk_client drivedesk_bus drivedesk_translations)
drivedesk_add_test(NAME tst_clientidlecheck LABELS unit integration TIMEOUT 120
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_clientidlecheck.cpp ${CMAKE_CURRENT_LIST_DIR}/ClientTestSupport.h
    LIBS drivedesk_client drivedesk_bus drivedesk_translations)

# Many seeded scans on a line that flips bits unflagged: slower than the others.
drivedesk_add_test(NAME tst_clientnoise LABELS integration TIMEOUT 600
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_clientnoise.cpp ${CMAKE_CURRENT_LIST_DIR}/ClientTestSupport.h
    LIBS drivedesk_client drivedesk_bus drivedesk_translations)

include(${CMAKE_CURRENT_LIST_DIR}/scanner.cmake)
