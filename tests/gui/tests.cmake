# The parameter editor's Widgets layer: item models and the editor delegate (offscreen).
drivedesk_add_test(NAME tst_parameterformat LABEL gui
    SOURCES gui/tst_parameterformat.cpp LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_parametermodel LABEL gui
    SOURCES gui/tst_parametermodel.cpp gui/GuiTestDrive.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_parameterfilter LABEL gui
    SOURCES gui/tst_parameterfilter.cpp gui/GuiTestDrive.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_parameterdelegate LABEL gui
    SOURCES gui/tst_parameterdelegate.cpp gui/GuiTestDrive.h LIBS drivedesk_ui)

foreach(area main edit monitor i18n)
    include(${CMAKE_CURRENT_LIST_DIR}/${area}.cmake)
endforeach()
