# The plant view: a plant file's links and drives, and core's PlantRun jobs on them (find, back
# up, verify, download) with progress per drive; a drive opens in the editor, two are compared;
# the backup folder's history (core/history) with a revision compared or restored.
target_sources(drivedesk_ui PRIVATE
    plant/PlantDock.cpp plant/PlantDockCommit.cpp plant/PlantDockJobs.cpp plant/PlantDock.h
    plant/PlantFeature.cpp plant/PlantFeature.h
    plant/PlantHistoryReading.cpp plant/PlantHistoryReading.h
    plant/PlantHistoryWindow.cpp plant/PlantHistoryWindow.h
    plant/PlantLinkDialog.cpp plant/PlantLinkDialog.h
    plant/PlantModel.cpp plant/PlantModelData.cpp plant/PlantModel.h
    plant/PlantReportDialog.cpp plant/PlantReportDialog.h
)
target_link_libraries(drivedesk_ui PUBLIC drivedesk_plant drivedesk_history)
