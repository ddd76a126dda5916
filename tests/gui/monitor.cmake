# The telegram monitor dock (offscreen, against the simulated drive).
drivedesk_add_test(NAME tst_telegrammonitor LABELS gui
    SOURCES gui/tst_telegrammonitor.cpp LIBS drivedesk_ui)
