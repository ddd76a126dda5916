# The HSP5 codec (seed 000's telegrams byte for byte) and its stream decoder (framing, garbage,
# the fuzz corpus replayed).
drivedesk_add_test(NAME tst_hsp5codec LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_hsp5codec.cpp LIBS drivedesk_hsp5)
drivedesk_add_test(NAME tst_hsp5decoder LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_hsp5decoder.cpp LIBS drivedesk_hsp5)
