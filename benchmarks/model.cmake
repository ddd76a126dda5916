# The parameter model: filling it and filter keystrokes with 5,000 parameters.
add_executable(bench_model ${CMAKE_CURRENT_LIST_DIR}/bench_model.cpp)
target_link_libraries(bench_model PRIVATE drivedesk_ui)
