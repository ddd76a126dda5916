# The DIN66019II / DIN66019 codec: seed 003's telegrams byte for byte, layouts, framing, and
# the fuzz corpus replayed.
drivedesk_add_test(NAME tst_dincodec LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_dincodec.cpp LIBS drivedesk_din)
