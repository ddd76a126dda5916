# core/scope: the clock, the sample store, the min/max levels, the CSV export and its reader, the
# recording file and the trigger; each links drivedesk_scope only.
drivedesk_add_test(NAME tst_scopeclock LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopeclock.cpp LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_scopestore LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopestore.cpp LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_scopepyramid LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopepyramid.cpp LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_scopecolumnmemo LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopecolumnmemo.cpp
            ${CMAKE_CURRENT_LIST_DIR}/ScopeTestRecording.h LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_scopecsv LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopecsv.cpp LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_scopecsvreader LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopecsvreader.cpp
            ${CMAKE_CURRENT_LIST_DIR}/ScopeTestRecording.h LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_scopefile LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopefile.cpp LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_scopetrigger LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopetrigger.cpp LIBS drivedesk_scope)
# Reading a recording: measurements between the cursors, math channels, the spectrum.
drivedesk_add_test(NAME tst_scopemeasurements LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopemeasurements.cpp
            ${CMAKE_CURRENT_LIST_DIR}/ScopeTestRecording.h LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_scopemath LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopemath.cpp
            ${CMAKE_CURRENT_LIST_DIR}/ScopeTestRecording.h LIBS drivedesk_scope)
drivedesk_add_test(NAME tst_scopespectrum LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopespectrum.cpp
            ${CMAKE_CURRENT_LIST_DIR}/ScopeTestRecording.h LIBS drivedesk_scope)
# Scope presets: a set-up saved and loaded again, bad files refused, where they are listed.
drivedesk_add_test(NAME tst_scopepreset LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopepreset.cpp LIBS drivedesk_scope)
# A second recording overlaid: read from its file, aligned at the trigger or the start.
drivedesk_add_test(NAME tst_scopeoverlay LABELS unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_scopeoverlay.cpp
            ${CMAKE_CURRENT_LIST_DIR}/ScopeTestRecording.h LIBS drivedesk_scope)
