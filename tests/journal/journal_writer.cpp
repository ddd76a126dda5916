// A program that writes to a journal, for the tests of several programs at once and of a disk
// that fills: journal_writer PATH COUNT SERIAL [FILE_SIZE_LIMIT]. Begins and completes COUNT
// entries for the drive with that serial number, then prints "wrote N" (the entries begun) and
// ends with 0, or prints the journal's error as well and ends with 1. With FILE_SIZE_LIMIT
// (bytes) no file of this process may grow past it, as on a full disk.
#include "JournalTestSupport.h"

#include <QCoreApplication>

#include <csignal>
#include <cstdio>

#include <sys/resource.h>

using namespace DriveDesk;

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList arguments = app.arguments();
    if (arguments.size() < 4) {
        std::fprintf(stderr, "usage: journal_writer PATH COUNT SERIAL [FILE_SIZE_LIMIT]\n");
        return 2;
    }
    if (arguments.size() > 4) {
        // Writing past the limit fails with EFBIG instead of ending the program.
        std::signal(SIGXFSZ, SIG_IGN);
        const rlim_t limit = arguments[4].toULongLong();
        const rlimit fileSize { limit, limit };
        if (::setrlimit(RLIMIT_FSIZE, &fileSize) != 0)
            return 2;
    }
    Journal journal(arguments[1]);
    const int count = arguments[2].toInt();
    int written = 0;
    bool ok = journal.open();
    for (int i = 0; ok && i < count; ++i) {
        JournalEntry entry = JournalTest::fullEntry();
        entry.time = {};
        entry.drive.serialNumber = arguments[3];
        entry.written = { qint32(i), QString::number(i) };
        const std::optional<qint64> id = journal.begin(entry);
        ok = id.has_value();
        if (ok) {
            ++written;
            ok = journal.complete(*id, entry.written, JournalOutcome::Written);
        }
    }
    std::printf("wrote %d\n", written);
    if (!ok) {
        std::fprintf(stderr, "%s\n", qPrintable(journal.errorString()));
        return 1;
    }
    return 0;
}
