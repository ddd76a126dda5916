# The compare window and its feature: two sides (the drive, files, defaults, sets), their
# comparison as a filtered table, and the chosen values written into one side.
target_sources(drivedesk_ui PRIVATE
    compare/CompareFeature.cpp compare/CompareFeature.h
    compare/CompareHost.h
    compare/ComparePaths.h
    compare/CompareWindow.cpp compare/CompareWindowSides.cpp compare/CompareWindowWrite.cpp
    compare/CompareWindow.h
    compare/ComparisonFilterModel.cpp compare/ComparisonFilterModel.h
    compare/ComparisonModel.cpp compare/ComparisonModel.h
)
