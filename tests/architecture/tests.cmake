# The window's include rule on the sources (docs/architecture.md): a feature folder includes no
# other feature, the frame includes none; only ui/main/WindowFeatures.cpp lists them all.
add_test(NAME tst_includerule
    COMMAND ${CMAKE_COMMAND} -DUI_DIR=${PROJECT_SOURCE_DIR}/ui
            -P ${CMAKE_CURRENT_LIST_DIR}/IncludeRule.cmake)
set_tests_properties(tst_includerule PROPERTIES LABELS unit TIMEOUT 60)

# No product file over 400 lines (docs/architecture.md).
add_test(NAME tst_filelength
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DMAX_LINES=400
            -P ${CMAKE_CURRENT_LIST_DIR}/FileLength.cmake)
set_tests_properties(tst_filelength PROPERTIES LABELS unit TIMEOUT 60)
