# The simulated drives on a byte stream, the in-process link, the TCP/pty server and
# drivedesk-sim. They need the bus, which needs the simulated drive and both codecs.
drivedesk_add_test(NAME tst_simulatedbus LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_simulatedbus.cpp ${CMAKE_CURRENT_LIST_DIR}/BusTestSupport.h
    LIBS drivedesk_bus)
drivedesk_add_test(NAME tst_simulatedlink LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_simulatedlink.cpp ${CMAKE_CURRENT_LIST_DIR}/BusTestSupport.h
    LIBS drivedesk_bus drivedesk_translations)
drivedesk_add_test(NAME tst_simulatorserver LABELS unit integration
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_simulatorserver.cpp ${CMAKE_CURRENT_LIST_DIR}/BusTestSupport.h
    LIBS drivedesk_bus)
drivedesk_add_test(NAME tst_drivedesksim LABELS unit integration
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_drivedesksim.cpp ${CMAKE_CURRENT_LIST_DIR}/BusTestSupport.h
    LIBS drivedesk_bus)
target_compile_definitions(tst_drivedesksim PRIVATE
    DRIVEDESK_SIM_PROGRAM="$<TARGET_FILE:drivedesk-sim>")
add_dependencies(tst_drivedesksim drivedesk-sim)
