# Parameter files to and from the drive: the download with its last look, progress and report.
target_sources(drivedesk_ui PRIVATE
    transfer/DownloadDialog.cpp transfer/DownloadDialog.h
    transfer/DownloadFeature.cpp transfer/DownloadFeature.h
)
