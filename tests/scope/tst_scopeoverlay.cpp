#include "ScopeTestRecording.h"

#include "scope/ScopeFileWriter.h"
#include "scope/ScopeOverlay.h"

#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ScopeTest;

namespace {

// A step on channel 1 at `stepMs`: 0 before, 1000 from then on; one sample every 2 ms from
// `firstMs` to `lastMs`.
ScopeRecording stepRecording(qint64 firstMs, qint64 lastMs, qint64 stepMs)
{
    ScopeRecording recording;
    recording.channels[0] = scaledChannel(0x0203, QStringLiteral("ru.03"),
                                          QStringLiteral("Actual frequency"), 10, kHz);
    for (qint64 ms = firstMs; ms <= lastMs; ms += 2)
        append(recording, ms, ms >= stepMs ? 1000 : 0);
    return recording;
}

bool write(const ScopeRecording &recording, const QString &path)
{
    ScopeFileWriter writer;
    const SampleStore &samples = recording.buffer.samples();
    return writer.open(path, ScopeFileHeader::of(recording))
        && writer.append(samples, 0, samples.count()) && writer.close();
}

} // namespace

// An overlay: a recording read from its file and put on the shown recording's time axis at
// the triggers or at the first samples, falling back to the first samples, and saying why,
// where a trigger is missing.
class TestScopeOverlay : public QObject
{
    Q_OBJECT

private slots:
    void init() { QVERIFY(m_dir.isValid()); }

    void alignedAtTheTrigger()
    {
        // the shown shot fired at 1400 ms; the file's, taken in another session, at 90,250 ms
        ScopeRecording shown = stepRecording(1000, 3000, 1400);
        shown.triggerMs = 1400;
        ScopeRecording earlier = stepRecording(90'000, 91'000, 90'250);
        earlier.triggerMs = 90'250;
        const QString path = m_dir.filePath(QStringLiteral("run2.ddscope"));
        QVERIFY(write(earlier, path));

        const ScopeOverlay overlay = ScopeOverlay::load(path);
        QVERIFY2(overlay.isLoaded(), qPrintable(overlay.error()));
        QCOMPARE(overlay.fileName(), QStringLiteral("run2.ddscope"));
        QCOMPARE(overlay.recording().buffer.count(), earlier.buffer.count());
        QCOMPARE(overlay.recording().triggerMs, std::optional<qint64>(90'250));

        const ScopeOverlayShift shift = overlay.shiftTo(shown, ScopeOverlayAlignment::Trigger);
        QCOMPARE(shift.alignment, ScopeOverlayAlignment::Trigger);
        QCOMPARE(shift.fallback, QString());
        // the overlay's trigger falls on the shown one's
        QCOMPARE(*overlay.recording().triggerMs + shift.shiftMs, *shown.triggerMs);
        QCOMPARE(shift.shiftMs, qint64(1400 - 90'250));
        // and so do their steps
        const SampleStore &samples = overlay.recording().buffer.samples();
        const qsizetype step = samples.lowerBound(90'250);
        QCOMPARE(samples.value(step - 1, 0), 0);
        QCOMPARE(samples.value(step, 0), 1000);
        QCOMPARE(samples.time(step) + shift.shiftMs, qint64(1400));
        QCOMPARE(overlay.label(QStringLiteral("ru.03 Actual frequency")),
                 QStringLiteral("ru.03 Actual frequency (overlay: run2.ddscope)"));
    }

    void alignedAtTheStart()
    {
        ScopeRecording shown = stepRecording(1000, 3000, 1400);
        shown.triggerMs = 1400;
        ScopeRecording earlier = stepRecording(90'000, 91'000, 90'250);
        earlier.triggerMs = 90'250;
        const QString path = m_dir.filePath(QStringLiteral("run2.ddscope"));
        QVERIFY(write(earlier, path));
        const ScopeOverlay overlay = ScopeOverlay::load(path);
        QVERIFY(overlay.isLoaded());

        const ScopeOverlayShift shift = overlay.shiftTo(shown, ScopeOverlayAlignment::Start);
        QCOMPARE(shift.alignment, ScopeOverlayAlignment::Start);
        QCOMPARE(shift.fallback, QString());
        QCOMPARE(overlay.recording().firstTime() + shift.shiftMs, qint64(1000));
    }

    void withoutATriggerItFallsBackToTheStart_data()
    {
        QTest::addColumn<bool>("shownHasTrigger");
        QTest::addColumn<bool>("overlayHasTrigger");
        QTest::addColumn<QString>("fallback");
        QTest::newRow("overlay none") << true << false
                                      << QStringLiteral("the overlay run1.ddscope has no trigger "
                                                        "(it is no single shot)");
        QTest::newRow("shown none")
            << false << true
            << QStringLiteral("the recording shown has no trigger (it is no single shot)");
        QTest::newRow("neither")
            << false << false
            << QStringLiteral("the overlay run1.ddscope has no trigger (it is no single shot)");
    }

    void withoutATriggerItFallsBackToTheStart()
    {
        QFETCH(bool, shownHasTrigger);
        QFETCH(bool, overlayHasTrigger);
        QFETCH(QString, fallback);
        ScopeRecording shown = stepRecording(1000, 3000, 1400);
        if (shownHasTrigger)
            shown.triggerMs = 1400;
        ScopeRecording earlier = stepRecording(500, 900, 600);
        if (overlayHasTrigger)
            earlier.triggerMs = 600;
        const QString path = m_dir.filePath(QStringLiteral("run1.ddscope"));
        QVERIFY(write(earlier, path));
        const ScopeOverlay overlay = ScopeOverlay::load(path);
        QVERIFY(overlay.isLoaded());

        const ScopeOverlayShift shift = overlay.shiftTo(shown, ScopeOverlayAlignment::Trigger);
        QCOMPARE(shift.alignment, ScopeOverlayAlignment::Start);
        QCOMPARE(shift.fallback, fallback);
        QCOMPARE(shift.shiftMs, qint64(1000 - 500));
    }

    // Before the shown recording has samples, the overlay starts at its time 0.
    void anEmptyRecordingShownTakesItFromZero()
    {
        const QString path = m_dir.filePath(QStringLiteral("run1.ddscope"));
        QVERIFY(write(stepRecording(500, 900, 600), path));
        const ScopeOverlay overlay = ScopeOverlay::load(path);
        QVERIFY(overlay.isLoaded());
        QCOMPARE(overlay.shiftTo(ScopeRecording(), ScopeOverlayAlignment::Start).shiftMs,
                 qint64(-500));
    }

    void aFileThatCannotBeReadSaysWhy()
    {
        const QString path = m_dir.filePath(QStringLiteral("missing.ddscope"));
        const ScopeOverlay overlay = ScopeOverlay::load(path);
        QVERIFY(!overlay.isLoaded());
        QVERIFY2(overlay.error().contains(path), qPrintable(overlay.error()));
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestScopeOverlay)
#include "tst_scopeoverlay.moc"
