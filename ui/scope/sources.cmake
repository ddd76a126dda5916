# The scope's chart: QCustomPlot fed the recording's decimated min/max points on a redraw
# timer, the channels' traces and value axes, two cursors and their read-out (docs/scope.md).
target_sources(drivedesk_ui PRIVATE
    scope/ScopeChart.cpp scope/ScopeChartExport.cpp scope/ScopeChartInput.cpp scope/ScopeChart.h
    scope/ScopeCursorReadout.cpp scope/ScopeCursorReadout.h
    scope/ScopeCursors.cpp scope/ScopeCursors.h
    scope/ScopeCursorTable.cpp scope/ScopeCursorTable.h
    scope/ScopeTraces.cpp scope/ScopeTraces.h
    scope/QCustomPlotInclude.h
)
