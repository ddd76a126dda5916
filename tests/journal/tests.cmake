# core/journal: the journal of the values written. Its storage and filters; the files it cannot
# write or read; several programs writing at once (journal_writer, started twice); the command
# that reads it.
drivedesk_add_test(NAME tst_journal LABELS unit SOURCES journal/tst_journal.cpp
    LIBS drivedesk_journal)
drivedesk_add_test(NAME tst_journalfilter LABELS unit SOURCES journal/tst_journalfilter.cpp
    LIBS drivedesk_journal)
# What a revert writes, the last change of each value and its text.
drivedesk_add_test(NAME tst_journalrevert LABELS unit SOURCES journal/tst_journalrevert.cpp
    LIBS drivedesk_journal)

add_executable(journal_writer journal/journal_writer.cpp)
target_link_libraries(journal_writer PRIVATE drivedesk_journal)
drivedesk_add_test(NAME tst_journalproblems LABELS integration
    SOURCES journal/tst_journalproblems.cpp LIBS drivedesk_journal)
drivedesk_add_test(NAME tst_journalprocesses LABELS integration
    SOURCES journal/tst_journalprocesses.cpp LIBS drivedesk_journal)
foreach(test tst_journalproblems tst_journalprocesses)
    add_dependencies(${test} journal_writer)
    target_compile_definitions(${test} PRIVATE JOURNAL_WRITER="$<TARGET_FILE:journal_writer>")
endforeach()

drivedesk_add_test(NAME tst_clijournal LABELS integration SOURCES journal/tst_clijournal.cpp
    LIBS drivedesk_cli)
add_dependencies(tst_clijournal drivedesk-cli)

# drivedesk-cli write journals what it writes, against drivedesk-sim read again; a journal that
# cannot take the entry stops the write unsent.
drivedesk_add_test(NAME tst_journalwrites LABELS integration SOURCES journal/tst_journalwrites.cpp
    LIBS drivedesk_journal drivedesk_cli)
add_dependencies(tst_journalwrites drivedesk-cli drivedesk-sim)

# The download journals what it writes: DownloadRun in process against the simulated drive, read
# again, and stopped half way.
drivedesk_add_test(NAME tst_journaldownload LABELS integration
    SOURCES journal/tst_journaldownload.cpp LIBS drivedesk_session drivedesk_bus)
# drivedesk-cli download against drivedesk-sim: journaled, killed half way, with a journal that
# cannot be written, and without one.
drivedesk_add_test(NAME tst_clidownloadjournal LABELS integration
    SOURCES journal/tst_clidownloadjournal.cpp LIBS drivedesk_journal)
add_dependencies(tst_clidownloadjournal drivedesk-cli drivedesk-sim)
# drivedesk-cli journal revert against drivedesk-sim read again; bad entries write nothing.
drivedesk_add_test(NAME tst_journalrevertcli LABELS integration
    SOURCES journal/tst_journalrevertcli.cpp LIBS drivedesk_journal drivedesk_cli)
add_dependencies(tst_journalrevertcli drivedesk-cli drivedesk-sim)
