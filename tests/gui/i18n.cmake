# The English and German catalogues: complete, and loaded from the resource path drivedesk uses.
# translations/CMakeLists.txt sets DRIVEDESK_QM_FILES: the catalogues it builds for drivedesk.
if(NOT DRIVEDESK_QM_FILES)
    message(FATAL_ERROR "tst_translations needs the catalogues of translations/")
endif()
drivedesk_add_test(NAME tst_translations LABELS gui
    SOURCES gui/tst_translations.cpp LIBS drivedesk_ui)
qt_add_resources(tst_translations "tst_translations_catalogues" PREFIX "/i18n"
    BASE ${DRIVEDESK_QM_DIR} FILES ${DRIVEDESK_QM_FILES})
add_dependencies(tst_translations drivedesk_lrelease)
target_compile_definitions(tst_translations PRIVATE
    DRIVEDESK_TRANSLATIONS_DIR="${PROJECT_SOURCE_DIR}/translations")
