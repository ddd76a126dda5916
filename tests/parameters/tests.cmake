# Parameter metadata: properties, display scaling, plaintexts, ids, parameter files, and the
# format values are shown and typed in.
drivedesk_add_test(NAME tst_displayscaling LABELS unit
    SOURCES parameters/tst_displayscaling.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_parameterproperties LABELS unit
    SOURCES parameters/tst_parameterproperties.cpp LIBS drivedesk_parameters drivedesk_translations)
drivedesk_add_test(NAME tst_plaintexts LABELS unit
    SOURCES parameters/tst_plaintexts.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_parameterid LABELS unit
    SOURCES parameters/tst_parameterid.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_drivedescription LABELS unit
    SOURCES parameters/tst_drivedescription.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_parameterdocument LABELS unit
    SOURCES parameters/tst_parameterdocument.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_parameterfile LABELS unit
    SOURCES parameters/tst_parameterfile.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_metadatacache LABELS unit
    SOURCES parameters/tst_metadatacache.cpp LIBS drivedesk_parameters)
drivedesk_add_test(NAME tst_parameterformat LABELS unit
    SOURCES parameters/tst_parameterformat.cpp parameters/EditorSampleDrive.h
    LIBS drivedesk_parameters)
# How telegrams read for a user (the telegram monitor's meanings).
drivedesk_add_test(NAME tst_telegramtext LABELS unit
    SOURCES parameters/tst_telegramtext.cpp LIBS drivedesk_parameters)

# Comparing two descriptions of a drive (the diff of two parameter files).
drivedesk_add_test(NAME tst_parametercomparison LABELS unit
    SOURCES parameters/tst_parametercomparison.cpp parameters/EditorSampleDrive.h
    LIBS drivedesk_parameters)
# The CSV export for spreadsheets.
drivedesk_add_test(NAME tst_parametercsv LABELS unit
    SOURCES parameters/tst_parametercsv.cpp parameters/EditorSampleDrive.h
    LIBS drivedesk_parameters drivedesk_translations)
# The compare view's comparison: every value of both sides with its state, and what writing the
# chosen values puts into a file or hands a download.
drivedesk_add_test(NAME tst_comparisontable LABELS unit
    SOURCES parameters/tst_comparisontable.cpp parameters/EditorSampleDrive.h
    LIBS drivedesk_parameters)
# The metadata that makes a drive without identification the kind of a file (download's check).
drivedesk_add_test(NAME tst_metadatamatch LABELS unit
    SOURCES parameters/tst_metadatamatch.cpp LIBS drivedesk_parameters)
