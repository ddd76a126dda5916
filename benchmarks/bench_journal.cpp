// The journal of the values written (docs/journal.md), on a file in a temporary folder of the
// disk /tmp is on (or the folder given as the first argument):
//  1. one value's entry, begun and completed (Journal::begin + Journal::complete), as every
//     write adds it to an edit's round trip: per entry, the median, 99th and 99.9th
//     percentile and slowest of kEntries, in each of kRuns runs (goal: well under 1 ms), with
//     the entries over 1 ms and how many of them the scheduler preempted (an involuntary
//     context switch: the machine was busy) or that waited (a voluntary one: the disk, a lock);
//     and close(), whose checkpoint syncs the disk;
//  2. a journal of 100,000 entries of 12 drives, filtered to one drive (by serial number and by
//     LINK@ADDRESS), to one parameter and to one hour: the query alone and with the table
//     printed, kRuns times each, in wall time and in the thread's CPU time (which a busy
//     machine does not stretch) (goal: one drive under 200 ms).
// Asserts nothing; prints the figures.
#include "journal/Journal.h"
#include "journal/JournalFormat.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>

using namespace DriveDesk;

namespace {

constexpr int kRuns = 5;
constexpr int kEntries = 5000;
constexpr int kJournalEntries = 100000;
constexpr int kDrives = 12;

JournalEntry entryFor(int i)
{
    JournalEntry entry;
    const int drive = i % kDrives;
    entry.drive.link = QStringLiteral("tcp:10.0.0.%1:5020").arg(1 + drive / 4);
    entry.drive.protocol = QStringLiteral("din66019ii");
    entry.drive.address = 1 + drive % 4;
    entry.drive.kind = QStringLiteral("F5 COMPACT 12.F5.C1G-3A0A");
    entry.drive.softwareVersion = QStringLiteral("1.80");
    entry.drive.serialNumber = QStringLiteral("SN%1").arg(100000 + drive);
    const int parameter = (i / kDrives) % 200;
    entry.parameterId = QStringLiteral("op.%1").arg(parameter, 2, 10, QLatin1Char('0'));
    entry.parameterAddress = quint16(0x0A00 + parameter);
    entry.parameterName = QStringLiteral("Parameter %1").arg(parameter);
    entry.set = i % 8;
    entry.before = { qint32(i), QStringLiteral("%1.00 Hz").arg(i % 500) };
    entry.written = { qint32(i + 1), QStringLiteral("%1.00 Hz").arg(i % 500 + 1) };
    return entry;
}

struct ContextSwitches
{
    long voluntary = 0;
    long involuntary = 0;
};

ContextSwitches contextSwitches()
{
    rusage usage {};
    ::getrusage(RUSAGE_THREAD, &usage);
    return { usage.ru_nvcsw, usage.ru_nivcsw };
}

double percentile(QList<double> values, double fraction)
{
    std::sort(values.begin(), values.end());
    return values.at(qMin(values.size() - 1, qsizetype(fraction * values.size())));
}

// "median 12.3 (min 11.0, max 14.2)" of several runs' figures.
QByteArray spread(const QList<double> &runs, const char *format)
{
    const auto number
        = [format](double value) { return QString::asprintf(format, value).toUtf8(); };
    return "median " + number(percentile(runs, 0.5)) + " (min "
        + number(*std::min_element(runs.begin(), runs.end())) + ", max "
        + number(*std::max_element(runs.begin(), runs.end())) + ")";
}

void beginAndComplete(const QString &folder)
{
    QList<double> medians, p99s, p999s, slowest, closing;
    int over = 0;
    int preempted = 0;
    int waited = 0;
    for (int run = 0; run < kRuns; ++run) {
        const QString path = QStringLiteral("%1/entries-%2.sqlite").arg(folder).arg(run);
        Journal journal(path);
        if (!journal.open()) {
            std::printf("%s\n", qPrintable(journal.errorString()));
            return;
        }
        QList<double> microseconds;
        microseconds.reserve(kEntries);
        QElapsedTimer timer;
        for (int i = 0; i < kEntries; ++i) {
            const JournalEntry entry = entryFor(i);
            const ContextSwitches before = contextSwitches();
            timer.start();
            const std::optional<qint64> id = journal.begin(entry);
            const bool ok = id && journal.complete(*id, entry.written, JournalOutcome::Written);
            microseconds << timer.nsecsElapsed() / 1e3;
            if (microseconds.last() > 1000) {
                const ContextSwitches after = contextSwitches();
                ++over;
                preempted += after.involuntary > before.involuntary ? 1 : 0;
                waited += after.voluntary > before.voluntary ? 1 : 0;
            }
            if (!ok) {
                std::printf("%s\n", qPrintable(journal.errorString()));
                return;
            }
        }
        medians << percentile(microseconds, 0.5);
        p99s << percentile(microseconds, 0.99);
        p999s << percentile(microseconds, 0.999);
        slowest << *std::max_element(microseconds.begin(), microseconds.end());
        timer.start();
        journal.close();
        closing << timer.nsecsElapsed() / 1e6;
    }
    std::printf("begin + complete, one entry (%d entries a run, %d runs), in us:\n", kEntries,
                kRuns);
    std::printf("  median of a run:  %s\n", spread(medians, "%.0f").constData());
    std::printf("  99th percentile:  %s\n", spread(p99s, "%.0f").constData());
    std::printf("  99.9th:           %s\n", spread(p999s, "%.0f").constData());
    std::printf("  slowest entry:    %s\n", spread(slowest, "%.0f").constData());
    std::printf("  over 1 ms: %d of %d entries; %d of them preempted, %d waited\n", over,
                kRuns * kEntries, preempted, waited);
    std::printf("close() (the last checkpoint), in ms: %s\n", spread(closing, "%.1f").constData());
}

double cpuMs()
{
    timespec time {};
    ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &time);
    return time.tv_sec * 1e3 + time.tv_nsec / 1e6;
}

void query(Journal &journal, const char *what, const JournalFilter &filter)
{
    QList<double> queryMs, tableMs, queryCpuMs, tableCpuMs;
    qsizetype found = 0;
    for (int run = 0; run < kRuns; ++run) {
        QElapsedTimer timer;
        timer.start();
        const double cpuStart = cpuMs();
        const std::optional<QList<JournalEntry>> entries = journal.entries(filter);
        queryMs << timer.nsecsElapsed() / 1e6;
        queryCpuMs << cpuMs() - cpuStart;
        if (!entries) {
            std::printf("%s\n", qPrintable(journal.errorString()));
            return;
        }
        const QByteArray table = JournalFormat::table(*entries).toUtf8();
        tableMs << timer.nsecsElapsed() / 1e6;
        tableCpuMs << cpuMs() - cpuStart;
        found = entries->size();
    }
    std::printf("  %-28s %6lld entries, in ms:\n", what, qlonglong(found));
    std::printf("    query            %s, CPU %s\n", spread(queryMs, "%.1f").constData(),
                spread(queryCpuMs, "%.1f").constData());
    std::printf("    with the table   %s, CPU %s\n", spread(tableMs, "%.1f").constData(),
                spread(tableCpuMs, "%.1f").constData());
}

void filtered(const QString &folder)
{
    const QString path = folder + QStringLiteral("/large.sqlite");
    {
        Journal journal(path);
        if (!journal.open()) {
            std::printf("%s\n", qPrintable(journal.errorString()));
            return;
        }
        QElapsedTimer timer;
        timer.start();
        const QDateTime start = QDateTime::currentDateTimeUtc().addDays(-30);
        for (int i = 0; i < kJournalEntries; ++i) {
            JournalEntry entry = entryFor(i);
            entry.time = start.addSecs(i * 20); // 100,000 writes over 23 days
            const std::optional<qint64> id = journal.begin(entry);
            if (!id || !journal.complete(*id, entry.written, JournalOutcome::Written)) {
                std::printf("%s\n", qPrintable(journal.errorString()));
                return;
            }
        }
        std::printf("%d entries of %d drives written (begin + complete each) in %.1f s\n",
                    kJournalEntries, kDrives, timer.nsecsElapsed() / 1e9);
    }
    Journal journal(path);
    if (!journal.open(Journal::Access::Read)) {
        std::printf("%s\n", qPrintable(journal.errorString()));
        return;
    }
    QString error;
    std::printf("queries over %d entries, %d runs each:\n", kJournalEntries, kRuns);
    JournalFilter bySerial;
    bySerial.setDrive(QStringLiteral("SN100005"), &error);
    query(journal, "--drive SN100005", bySerial);
    JournalFilter byLink;
    byLink.setDrive(QStringLiteral("tcp:10.0.0.2:5020@2"), &error);
    query(journal, "--drive tcp:10.0.0.2:5020@2", byLink);
    JournalFilter byParameter;
    byParameter.setParameter(QStringLiteral("op.17"), &error);
    query(journal, "--parameter op.17", byParameter);
    JournalFilter oneHour;
    const QDateTime hour = QDateTime::currentDateTime().addDays(-20);
    oneHour.setSince(hour.toString(QStringLiteral("yyyy-MM-ddTHH:00")), &error);
    oneHour.setUntil(hour.toString(QStringLiteral("yyyy-MM-ddTHH:59")), &error);
    query(journal, "--since/--until one hour", oneHour);
    JournalFilter driveAndParameter = bySerial;
    driveAndParameter.setParameter(QStringLiteral("op.17"), &error);
    query(journal, "--drive and --parameter", driveAndParameter);
    query(journal, "everything", {});
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QTemporaryDir temporary(app.arguments().size() > 1
                                ? app.arguments().at(1) + QStringLiteral("/bench_journal-XXXXXX")
                                : QString());
    if (!temporary.isValid()) {
        std::printf("cannot make a temporary folder: %s\n", qPrintable(temporary.errorString()));
        return 1;
    }
    std::printf("journal files in %s\n", qPrintable(temporary.path()));
    beginAndComplete(temporary.path());
    filtered(temporary.path());
    return 0;
}
