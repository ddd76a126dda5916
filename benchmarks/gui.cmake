# The window's event loop during a scan and during polling, 5,000 simulated parameters.
add_executable(bench_gui_stall ${CMAKE_CURRENT_LIST_DIR}/bench_gui_stall.cpp)
target_link_libraries(bench_gui_stall PRIVATE drivedesk_ui)
# The scope chart's redraws: the whole recording, every point for comparison, the roll tick.
add_executable(bench_scope_view ${CMAKE_CURRENT_LIST_DIR}/bench_scope_view.cpp)
target_link_libraries(bench_scope_view PRIVATE drivedesk_ui)
