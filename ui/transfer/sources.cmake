# Parameters to and from the drive and files: the download with its last look, progress and
# report; the CSV export.
target_sources(drivedesk_ui PRIVATE
    transfer/DownloadDialog.cpp transfer/DownloadDialog.h
    transfer/DownloadFeature.cpp transfer/DownloadFeature.h
    transfer/ExportFeature.cpp transfer/ExportFeature.h
    transfer/SaveDriveFeature.cpp transfer/SaveDriveFeature.h
)
