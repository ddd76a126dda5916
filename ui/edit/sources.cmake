# Editing: writes with read-back and undo, copy and refresh, polling, the password level.
target_sources(drivedesk_ui PRIVATE
    edit/AccessController.cpp edit/AccessController.h
    edit/EditController.cpp edit/EditJobs.cpp edit/EditController.h
    edit/PasswordDialog.cpp edit/PasswordDialog.h
    edit/PollingController.cpp edit/PollingController.h
    edit/ReplyWatch.h
    edit/SetsDialog.cpp edit/SetsDialog.h
    edit/ValueReadBatch.cpp edit/ValueReadBatch.h
    edit/ValueWriter.cpp edit/ValueWriter.h
    edit/WriteValueCommand.cpp edit/WriteValueCommand.h
)
