# Editing: writes with read-back and undo, edits of an open parameter file, copy and refresh,
# polling, the password level, and the window features that offer them.
target_sources(drivedesk_ui PRIVATE
    edit/AccessController.cpp edit/AccessController.h
    edit/AccessFeature.cpp edit/AccessFeature.h
    edit/DocumentEditor.cpp edit/DocumentEditor.h
    edit/EditController.cpp edit/EditJobs.cpp edit/EditController.h
    edit/EditingFeature.cpp edit/EditingFeature.h
    edit/WriteJournal.cpp edit/WriteJournal.h
    edit/PasswordDialog.cpp edit/PasswordDialog.h
    edit/PollingController.cpp edit/PollingController.h
    edit/PollingFeature.cpp edit/PollingFeature.h
    edit/SetsDialog.cpp edit/SetsDialog.h
    edit/SetsFeature.cpp edit/SetsFeature.h
    edit/ValueReadBatch.cpp edit/ValueReadBatch.h
    edit/ValueCommand.cpp edit/ValueCommand.h
)
