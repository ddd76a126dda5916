drivedesk_add_test(NAME tst_cli LABELS unit integration SOURCES cli/tst_cli.cpp LIBS drivedesk_parameters)
add_dependencies(tst_cli drivedesk-cli drivedesk-sim)
drivedesk_add_test(NAME tst_clitransfer LABELS integration SOURCES cli/tst_clitransfer.cpp LIBS Qt6::Core)
add_dependencies(tst_clitransfer drivedesk-cli drivedesk-sim)
