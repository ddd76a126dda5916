# The journal view (View > Journal), the last change in the table's tooltips, and revert.
target_sources(drivedesk_ui PRIVATE
    journal/JournalDock.cpp journal/JournalDock.h
    journal/JournalFeature.cpp journal/JournalFeature.h
    journal/JournalReader.cpp journal/JournalReader.h
    journal/JournalTableModel.cpp journal/JournalTableModel.h
)
