# The English and German catalogues: complete, and loaded from drivedesk_translations the way
# drivedesk and drivedesk-cli load them.
drivedesk_add_test(NAME tst_translations LABELS gui
    SOURCES gui/tst_translations.cpp LIBS drivedesk_ui drivedesk_translations)
target_compile_definitions(tst_translations PRIVATE
    DRIVEDESK_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    DRIVEDESK_TRANSLATIONS_DIR="${PROJECT_SOURCE_DIR}/translations")
# Alt+letter reaches one thing in each place: menus, the window with its docks, every dialog the
# menus open, in English and German.
drivedesk_add_test(NAME tst_mnemonics LABELS gui
    SOURCES gui/tst_mnemonics.cpp gui/tst_mainwindow_support.h LIBS drivedesk_ui drivedesk_translations)
