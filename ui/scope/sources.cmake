# The scope: the chart (QCustomPlot fed the recording's decimated min/max points on a redraw
# timer, the channels' traces and value axes, two cursors and their read-out, a second
# recording overlaid), the channels' panel, the spectrum window, and the dock and feature that
# record from the drive (docs/scope.md).
target_sources(drivedesk_ui PRIVATE
    scope/ScopeChart.cpp scope/ScopeChartExport.cpp scope/ScopeChartInput.cpp
    scope/ScopeChartView.cpp scope/ScopeChartOverlay.cpp scope/ScopeChart.h
    scope/ScopeCursorReadout.cpp scope/ScopeCursorReadout.h
    scope/ScopeCursors.cpp scope/ScopeCursors.h
    scope/ScopeCursorTable.cpp scope/ScopeCursorTable.h
    scope/ScopeMeasurementTable.cpp scope/ScopeMeasurementTable.h
    scope/ScopeMathChannels.cpp scope/ScopeMathChannels.h
    scope/ScopeMathDialog.cpp scope/ScopeMathDialog.h
    scope/ScopeMathTraces.cpp scope/ScopeMathTraces.h
    scope/ScopeSpectrumPlot.cpp scope/ScopeSpectrumPlot.h
    scope/ScopeSpectrumView.cpp scope/ScopeSpectrumView.h
    scope/ScopeGraph.cpp scope/ScopeGraph.h scope/ScopeLegendItem.cpp scope/ScopeLegendItem.h
    scope/ScopeTraces.cpp scope/ScopeTraces.h
    scope/ScopeOverlayTraces.cpp scope/ScopeOverlayTraces.h
    scope/QCustomPlotInclude.h
    scope/ScopeChannelPanel.cpp scope/ScopeChannelPanel.h
    scope/ScopeDock.cpp scope/ScopeDockRecording.cpp scope/ScopeDockFiles.cpp
    scope/ScopeDockOverlay.cpp
    scope/ScopeDockToolBars.cpp scope/ScopeDockPresets.cpp scope/ScopeDock.h
    scope/ScopeFeature.cpp scope/ScopeFeature.h
)
