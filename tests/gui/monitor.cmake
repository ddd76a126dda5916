# The telegram monitor dock (offscreen, against the simulated drive).
if(TARGET drivedesk_ui)
    drivedesk_add_test(NAME tst_telegrammonitor LABEL gui
        SOURCES gui/tst_telegrammonitor.cpp LIBS drivedesk_ui)
    # resources/CMakeLists.txt sets it when the application icon is built into drivedesk_ui.
    if(DRIVEDESK_ICON_RESOURCE)
        target_compile_definitions(tst_telegrammonitor PRIVATE DRIVEDESK_ICON_RESOURCE)
    endif()
endif()
