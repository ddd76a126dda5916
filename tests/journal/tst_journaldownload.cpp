// The download journals every value it writes (docs/journal.md): DownloadRun against the
// simulated drive in process, one entry per value, agreeing with the drive read again; a
// download stopped half way journals what it never sent as not sent.
#include "../client/ClientTestSupport.h"

#include "journal/Journal.h"
#include "parameters/ParameterList.h"
#include "session/DownloadRun.h"
#include "session/EditJournal.h"

#include <QTemporaryDir>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

namespace {

constexpr quint16 kFixedSpeed1 = 0x0314; // op.20, 8 sets

DriveDescription scanned(Session &session, bool parameterList)
{
    ScanOptions options;
    options.parameterList = parameterList;
    const QFuture<DriveDescription> scan = session.client->scan(options);
    return waitFinished(scan, 60000) ? scan.result() : DriveDescription {};
}

std::optional<qint32> valueOf(const DriveDescription &drive, quint16 address,
                              std::optional<int> set)
{
    const ParameterDescription *parameter = drive.find(address);
    return parameter ? parameter->values[std::size_t(set.value_or(0))] : std::nullopt;
}

QList<JournalEntry> entriesOf(const QString &path)
{
    Journal journal(path);
    if (!journal.open(Journal::Access::Read))
        return {};
    return journal.entries().value_or(QList<JournalEntry>());
}

} // namespace

class TestJournalDownload : public QObject
{
    Q_OBJECT

private:
    // The download of `file` to the session's drive, journaled into `journal` (none: not);
    // `onProgress` runs at each value written. The run, finished or failed.
    std::unique_ptr<DownloadRun> download(Session &session, const DriveDescription &file,
                                          EditJournal *journal,
                                          std::function<void(DownloadRun &)> onProgress = {})
    {
        auto run = std::make_unique<DownloadRun>(session.client.get(), Protocol::Hsp5, file);
        run->setJournal(journal);
        DownloadRun *raw = run.get();
        connect(raw, &DownloadRun::planned, raw, [raw] { raw->write(); });
        if (onProgress) {
            connect(raw, &DownloadRun::progress, raw, [raw, onProgress] {
                if (raw->stage() == DownloadRun::Stage::Writing)
                    onProgress(*raw);
            });
        }
        run->start();
        [[maybe_unused]] const bool done = QTest::qWaitFor(
            [raw] { return raw->stage() == DownloadRun::Stage::Done; }, 60000);
        return run;
    }

    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void aDownloadJournalsEachValueItWrites()
    {
        Session session(simulated(Protocol::Hsp5, fast()));
        QVERIFY(session.connected());
        const DriveDescription before = scanned(session, false);
        DriveDescription file = scanned(session, true);
        for (int set : { 1, 3, 6 })
            file.find(kFixedSpeed1)->values[std::size_t(set)] = 200 + set;
        file.find(kMaxSpeedForward)->values[2] = 2500;
        file.find(kMotorVoltage)->values[0] = 390;

        const QString path = m_dir.filePath(QStringLiteral("download.sqlite"));
        Journal journal(path);
        QVERIFY2(journal.open(), qPrintable(journal.errorString()));
        EditJournal entries(&journal, {}, QStringLiteral("download of f5.json"));
        const std::unique_ptr<DownloadRun> run = download(session, file, &entries);
        QCOMPARE(run->stage(), DownloadRun::Stage::Done);
        const int values = run->plan().valueCount();
        QVERIFY(values >= 5);

        const DriveDescription after = scanned(session, false);
        QVERIFY(after.incompleteReason.isEmpty());
        const QList<JournalEntry> journaled = entriesOf(path);
        QCOMPARE(journaled.size(), values);
        int fixedSpeed = 0;
        for (const JournalEntry &entry : journaled) {
            const QString what = QStringLiteral("%1 set %2").arg(entry.parameterId).arg(entry.set.value_or(-1));
            QVERIFY2(entry.outcome == JournalOutcome::Written, qPrintable(what + entry.outcomeText()));
            QCOMPARE(entry.jobDescription, QStringLiteral("download of f5.json"));
            QCOMPARE(entry.drive.protocol, QStringLiteral("hsp5"));
            QVERIFY(!entry.drive.serialNumber.isEmpty());
            QVERIFY(entry.completedTime.isValid());
            // What the download read before it wrote, what it wrote, and what the drive holds.
            if (entry.before.raw) // a write-only value is never read
                QVERIFY2(entry.before.raw == valueOf(before, entry.parameterAddress, entry.set), qPrintable(what));
            QVERIFY2(entry.written.raw == valueOf(file, entry.parameterAddress, entry.set), qPrintable(what));
            if (const std::optional<qint32> held = valueOf(after, entry.parameterAddress, entry.set);
                held && entry.readBack.raw) {
                QVERIFY2(entry.readBack.raw == held, qPrintable(what));
            }
            if (entry.parameterAddress == kFixedSpeed1) {
                ++fixedSpeed;
                QCOMPARE(entry.readBack.raw, 200 + *entry.set);
                QCOMPARE(entry.readBack.text, QStringLiteral("%1 1/min").arg(200 + *entry.set));
            }
        }
        QCOMPARE(fixedSpeed, 3);
    }

    // Stopped after the first value: what went out is journaled with its outcome, what never
    // went out as not sent, and the drive still holds the value before.
    void aStoppedDownloadJournalsWhatItNeverSentAsNotSent()
    {
        SimulationOptions paced;
        paced.paced = true; // at the line's baud rate: the stop comes while values are left
        Session session(simulated(Protocol::Hsp5, paced));
        QVERIFY(session.connected());
        DriveDescription file = scanned(session, true);
        int changed = 0;
        for (GroupDescription &group : file.groups) {
            if (group.id != QLatin1String("op") && group.id != QLatin1String("dr"))
                continue;
            for (ParameterDescription &parameter : group.parameters) {
                if (!parameter.isSetProgrammable() || !ParameterList::isWrittenByDownload(parameter))
                    continue;
                for (std::optional<qint32> &value : parameter.values) {
                    if (value && changed < 40) {
                        value = *value > parameter.minimum ? *value - 1 : *value + 1;
                        ++changed;
                    }
                }
            }
        }
        const QString path = m_dir.filePath(QStringLiteral("stopped.sqlite"));
        Journal journal(path);
        QVERIFY2(journal.open(), qPrintable(journal.errorString()));
        EditJournal entries(&journal, {}, QStringLiteral("download of many.json"));
        const std::unique_ptr<DownloadRun> run
            = download(session, file, &entries, [](DownloadRun &r) { r.stop(); });
        QCOMPARE(run->stage(), DownloadRun::Stage::Done);

        const DriveDescription after = scanned(session, false);
        QVERIFY(after.incompleteReason.isEmpty());
        const QList<JournalEntry> journaled = entriesOf(path);
        QCOMPARE(journaled.size(), run->plan().valueCount());
        int written = 0;
        int notSent = 0;
        for (const JournalEntry &entry : journaled) {
            const QString what = QStringLiteral("%1 set %2: %3").arg(entry.parameterId).arg(entry.set.value_or(-1)).arg(entry.outcomeText());
            const std::optional<qint32> held = valueOf(after, entry.parameterAddress, entry.set);
            QVERIFY2(entry.outcome != JournalOutcome::Unknown, qPrintable(what));
            if (entry.outcome == JournalOutcome::Written) {
                ++written;
                QVERIFY2(held == entry.written.raw, qPrintable(what));
            } else {
                ++notSent;
                QVERIFY2(entry.reason.startsWith(QStringLiteral("not sent: stopped by the user")),
                         qPrintable(what));
                if (entry.before.raw) // a write-only value is never read
                    QVERIFY2(held == entry.before.raw, qPrintable(what));
            }
        }
        QVERIFY(written > 0);
        QVERIFY2(notSent > 0, "the download ended before the stop reached it");
    }
};

QTEST_GUILESS_MAIN(TestJournalDownload)
#include "tst_journaldownload.moc"
