// drivedesk-cli scope: records the drive's scope data for a while and writes it as CSV.
#include "CliRunner.h"

#include "scope/ScopeCsv.h"
#include "scope/ScopeRecording.h"
#include "session/EditJournal.h"
#include "session/ScopeOfflineJob.h"
#include "session/ScopeRecorder.h"
#include "state/DriveState.h"
#include "state/ScopeChannelEdits.h"
#include "state/ValueEdits.h"

#include <QFutureWatcher>

namespace DriveDesk {

void CliRunner::runScope()
{
    // The scan finds the assignment parameters and every source's name, unit and scaling.
    ScanOptions metadata;
    metadata.values = false;
    metadata.plaintexts = false;
    scan(metadata, [this](const DriveDescription &drive) {
        if (!drive.incompleteReason.isEmpty())
            return fail(1, tr("the drive could not be read: %1").arg(drive.incompleteReason));
        ScopeAssignment choices;
        if (!m_request.channels.isEmpty()) {
            for (std::size_t channel = 0; channel < choices.size(); ++channel) {
                choices[channel] = ChannelAssignment{ChannelAssignment::kOff, 0x01};
                if (qsizetype(channel) >= m_request.channels.size())
                    continue;
                const QString &text = m_request.channels.at(qsizetype(channel));
                // A preset's channel left as the drive has it.
                if (text.isEmpty()) {
                    choices[channel].reset();
                    continue;
                }
                // "op.11@2": the source read from set 2.
                QString error;
                const std::optional<ScopeSourceText> source = ScopeSourceText::parse(text, &error);
                choices[channel] = source ? scopeSourceOn(*source, drive, &error) : std::nullopt;
                if (!choices[channel])
                    return fail(2, error);
            }
        }
        m_state->setDescription(drive);
        // Nothing to write, nothing to journal; else the journal names the drive by what it
        // says it is.
        const bool writes = !planScopeChannels(drive, choices).writes.isEmpty();
        if (!m_request.journalWrites || !writes)
            return assignChannels(choices, false);
        readIdentity(scopeAssignmentParameters(drive)->source[0],
                     [this, choices] { assignChannels(choices, true); });
    });
}

// Through the edit path, as `write` writes: ordered, journaled unless --no-journal, read back.
void CliRunner::assignChannels(const ScopeAssignment &choices, bool journaled)
{
    const DriveDescription drive = m_state->description();
    auto *edits = new ValueEdits(m_client.get(), m_state, this);
    if (journaled) {
        QString error;
        const bool opened = openJournal(&error);
        m_editJournal = std::make_unique<EditJournal>(
            m_journal.get(), EditJournal::driveOf(m_request.connection, drive),
            tr("scope channel assignment"));
        // A journal that cannot be opened refuses the writes, each saying why.
        if (!opened) {
            m_editJournal->setUnavailable(error);
            m_editJournal->setRemedy(tr("--no-journal writes without it"));
        }
        edits->setJournal(m_editJournal.get());
    }
    assignScopeChannels(*edits, drive, choices,
                        [this, edits, drive](const ScopeChannelsOutcome &outcome) {
        edits->deleteLater();
        if (outcome.refusedChoice)
            return fail(2, outcome.error);
        if (!outcome.error.isEmpty())
            return fail(outcome.connectionFailed ? 3 : 1,
                        tr("the channels could not be assigned: %1").arg(outcome.error));
        const ScopeChannels channels = scopeChannels(drive, outcome.assignment);
        if (m_request.offline)
            return readOfflineRecords(channels);
        record(channels);
    });
}

void CliRunner::record(const QList<ScopeChannel> &channels)
{
    if (std::none_of(channels.begin(), channels.end(),
                     [](const ScopeChannel &channel) { return channel.enabled; })) {
        return fail(2, tr("every scope channel of the drive is off: choose what to record with "
                          "--channels, e.g. --channels ru.3,ru.9"));
    }
    m_recording = std::make_unique<ScopeRecording>();
    m_recording->channels = channels;
    m_recording->source = m_request.connection.displayName();
    m_recorder = new ScopeRecorder(m_client.get(), this);
    connect(m_recorder, &ScopeRecorder::statusChanged, this,
            [this](const ScopeRecorderStatus &status) {
                const qint64 spanMs = m_recording->lastTime() - m_recording->firstTime();
                progressLine(int(std::min<qint64>(100, spanMs * 100 / m_request.durationMs)),
                             tr("recording: %1 s, %2 Hz, %3 lost, %4 failed")
                                 .arg(double(spanMs) / 1000.0, 0, 'f', 1)
                                 .arg(status.rateHz, 0, 'f', 0)
                                 .arg(status.counts.lost)
                                 .arg(status.counts.failed));
            });
    connect(m_recorder, &ScopeRecorder::finished, this, &CliRunner::recorded);
    if (!m_request.quiet) {
        QStringList titles;
        for (const int channel : m_recording->recordedChannels())
            titles << channels.at(channel).title(channel);
        m_err << tr("recording %1 for %2 s; Ctrl+C stops and writes what was recorded")
                     .arg(titles.join(QStringLiteral(", ")))
                     .arg(double(m_request.durationMs) / 1000.0)
              << '\n' << Qt::flush;
    }
    ScopeRecorderOptions options;
    options.polling.maxRateHz = m_request.rateHz;
    options.durationMs = m_request.durationMs;
    m_recorder->start(m_recording.get(), options);
}

void CliRunner::recorded(const ScopePollEnd &end)
{
    progressLine(-1, {});
    const ScopeRecorderStatus status = m_recorder->status();
    if (!writeScopeCsv())
        return;
    const double seconds = double(m_recording->lastTime() - m_recording->firstTime()) / 1000.0;
    m_out << tr("%1: %n sample(s) over %2 s, achieved %3 Hz", nullptr,
                int(m_recording->buffer.count()))
                 .arg(m_request.csvFile)
                 .arg(seconds, 0, 'f', 3)
                 .arg(status.averageHz, 0, 'f', 1)
          << QStringLiteral(" (") << tr("%1 lost, %2 failed").arg(end.counts.lost).arg(end.counts.failed)
          << QStringLiteral(")\n");
    if (!end.reason.isEmpty())
        return fail(1, tr("the recording ended early: %1").arg(end.reason));
    done();
}

bool CliRunner::writeScopeCsv()
{
    ScopeCsvOptions csv;
    csv.channels = m_recording->recordedChannels();
    QString error;
    if (!saveScopeCsv(m_request.csvFile, *m_recording, csv, &error)) {
        fail(1, error);
        return false;
    }
    return true;
}

void CliRunner::readOfflineRecords(const QList<ScopeChannel> &channels)
{
    auto *watcher = new QFutureWatcher<ScopeOfflineRecords>(this);
    connect(watcher, &QFutureWatcherBase::progressValueChanged, this, [this, watcher](int value) {
        progressLine(value * 100 / std::max(1, watcher->progressMaximum()),
                     tr("reading offline record %1 of %2").arg(value).arg(watcher->progressMaximum()));
    });
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, channels] {
        progressLine(-1, {});
        watcher->deleteLater();
        const ScopeOfflineRecords records = watcher->future().result();
        m_recording = offlineRecording(records, channels, m_request.connection.displayName());
        if (records.samples.isEmpty())
            return fail(1, records.error);
        if (!writeScopeCsv())
            return;
        m_out << tr("%1: %n offline record(s), one a millisecond assumed", nullptr,
                    int(records.samples.size()))
                     .arg(m_request.csvFile)
              << '\n';
        if (records.clipped > 0)
            m_err << tr("warning: %n record(s) had channel 3 or 4 beyond 16 bits and hold the "
                        "nearest 16-bit value", nullptr, int(records.clipped))
                  << '\n';
        if (!records.error.isEmpty())
            return fail(1, tr("the records could not all be read: %1").arg(records.error));
        done();
    });
    watcher->setFuture(m_client->run(std::make_shared<ScopeOfflineJob>()));
}

} // namespace DriveDesk
