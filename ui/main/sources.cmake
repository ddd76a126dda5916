# The window: MainWindow (the one frame), its dialogs, the favourites per drive, the recent
# connections, the start-up options and the list of features.
target_sources(drivedesk_ui PRIVATE
    main/ConnectionDialog.cpp main/ConnectionDialog.h
    main/DriveFavourites.cpp main/DriveFavourites.h
    main/DriveInfoDialog.cpp main/DriveInfoDialog.h
    main/FindDrivesDialog.cpp main/FindDrivesDialog.h
    main/MainWindow.cpp main/MainWindowActions.cpp main/MainWindowCommands.cpp
    main/MainWindowFiles.cpp main/MainWindowSession.cpp main/MainWindow.h
    main/RecentConnections.cpp main/RecentConnections.h
    main/StartupOptions.cpp main/StartupOptions.h
    main/WindowFeatures.cpp main/WindowFeatures.h
)
