# Links: connection settings, serial (socat pseudo-terminal pairs) and TCP.
drivedesk_add_test(NAME tst_connectionsettings LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_connectionsettings.cpp LIBS drivedesk_link)
drivedesk_add_test(NAME tst_connectionoptions LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_connectionoptions.cpp LIBS drivedesk_link)
drivedesk_add_test(NAME tst_seriallink LABELS unit integration
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_seriallink.cpp LIBS drivedesk_link)
drivedesk_add_test(NAME tst_tcplink LABELS unit integration
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_tcplink.cpp LIBS drivedesk_link)
# The links against drivedesk's own simulator (TCP and its pseudo-terminal).
drivedesk_add_test(NAME tst_linktosimulator LABELS unit integration
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_linktosimulator.cpp LIBS drivedesk_bus)
# Unix signals into the event loop, as the command-line programs take Ctrl+C.
drivedesk_add_test(NAME tst_signalnotifier LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_signalnotifier.cpp LIBS drivedesk_link)
# The alarm finer than a millisecond that paces the scope's polls and the simulated wire.
drivedesk_add_test(NAME tst_precisealarm LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_precisealarm.cpp LIBS drivedesk_link)
