# The parameter editor's Widgets layer: item models and the editor delegate (offscreen).
drivedesk_add_test(NAME tst_parametermodel LABELS gui
    SOURCES gui/tst_parametermodel.cpp parameters/EditorSampleDrive.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_parameterfilter LABELS gui
    SOURCES gui/tst_parameterfilter.cpp parameters/EditorSampleDrive.h LIBS drivedesk_ui)
drivedesk_add_test(NAME tst_parameterdelegate LABELS gui
    SOURCES gui/tst_parameterdelegate.cpp parameters/EditorSampleDrive.h LIBS drivedesk_ui)

foreach(area main edit monitor i18n compare scope plant)
    include(${CMAKE_CURRENT_LIST_DIR}/${area}.cmake)
endforeach()
