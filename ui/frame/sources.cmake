# What a feature sees of the window: the feature interface, the drive session, the parameter
# browser, the notice bar, the file problem box and the journal of a job's writes. Includes no feature and not the window.
target_sources(drivedesk_ui PRIVATE
    frame/DriveSession.cpp frame/DriveSession.h
    frame/FileProblem.cpp frame/FileProblem.h
    frame/FilterBar.cpp frame/FilterBar.h
    frame/FrameSupport.h
    frame/GroupListModel.cpp frame/GroupListModel.h
    frame/NoticeBar.cpp frame/NoticeBar.h
    frame/ParameterBrowser.cpp frame/ParameterBrowserSelection.cpp frame/ParameterBrowser.h
    frame/ParameterEditing.h
    frame/ParameterView.cpp frame/ParameterView.h
    frame/RunJournal.cpp frame/RunJournal.h
    frame/WindowFeature.h frame/WindowFrame.h
)
