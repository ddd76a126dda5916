# The telegram monitor dock (offscreen, against the simulated drive).
drivedesk_add_test(NAME tst_telegrammonitor LABEL gui
    SOURCES gui/tst_telegrammonitor.cpp LIBS drivedesk_ui)
