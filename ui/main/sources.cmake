# The frame: the main window, its dialogs and file commands, the drive session, the feature interface and the
# list of features, and the start-up options.
target_sources(drivedesk_ui PRIVATE
    main/ConnectionDialog.cpp main/ConnectionDialog.h
    main/DriveFavourites.cpp main/DriveFavourites.h
    main/DriveInfoDialog.cpp main/DriveInfoDialog.h
    main/DriveSession.cpp main/DriveSession.h
    main/FilterBar.cpp main/FilterBar.h
    main/FindDrivesDialog.cpp main/FindDrivesDialog.h
    main/FrameSupport.h
    main/GroupListModel.cpp main/GroupListModel.h
    main/MainWindow.cpp main/MainWindowActions.cpp main/MainWindowCommands.cpp
    main/MainWindowFiles.cpp main/MainWindowSession.cpp main/MainWindow.h
    main/NoticeBar.cpp main/NoticeBar.h
    main/ParameterBrowser.cpp main/ParameterBrowserSelection.cpp main/ParameterBrowser.h
    main/ParameterEditing.h
    main/ParameterView.cpp main/ParameterView.h
    main/RecentConnections.cpp main/RecentConnections.h
    main/StartupOptions.cpp main/StartupOptions.h
    main/WindowFeature.h main/WindowFrame.h
    main/WindowFeatures.cpp main/WindowFeatures.h
)
