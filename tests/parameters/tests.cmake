# Parameter metadata: properties, display scaling, plaintexts, ids, parameter files.
drivedesk_add_test(NAME tst_displayscaling LABEL unit
    SOURCES parameters/tst_displayscaling.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_parameterproperties LABEL unit
    SOURCES parameters/tst_parameterproperties.cpp LIBS drivedesk_parameters drivedesk_translations)
drivedesk_add_test(NAME tst_plaintexts LABEL unit
    SOURCES parameters/tst_plaintexts.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_parameterid LABEL unit
    SOURCES parameters/tst_parameterid.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_drivedescription LABEL unit
    SOURCES parameters/tst_drivedescription.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_parameterdocument LABEL unit
    SOURCES parameters/tst_parameterdocument.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_parameterfile LABEL unit
    SOURCES parameters/tst_parameterfile.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_metadatacache LABEL unit
    SOURCES parameters/tst_metadatacache.cpp LIBS drivedesk_parameters)
