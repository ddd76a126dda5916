#include "DownloadRun.h"

#include "parameters/SetList.h"
#include "session/WriteChangesJob.h"

#include <algorithm>

namespace DriveDesk {

DownloadRun::DownloadRun(DriveClient *client, Protocol protocol, DriveDescription file,
                         QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_protocol(protocol)
    , m_file(std::move(file))
{
    connect(&m_reading, &QFutureWatcher<DriveDescription>::progressTextChanged, this,
            [this](const QString &text) {
                emit progress(m_reading.progressValue(), m_reading.progressMaximum(), text);
            });
    connect(&m_reading, &QFutureWatcher<DriveDescription>::finished, this, &DownloadRun::onRead);
    connect(&m_writing, &QFutureWatcher<WriteOutcome>::progressValueChanged, this,
            [this](int written) {
                emit progress(written, int(m_plan.items.size()),
                              tr("writing %1 of %2").arg(written).arg(m_plan.items.size()));
            });
    connect(&m_writing, &QFutureWatcher<WriteOutcome>::resultsReadyAt, this,
            &DownloadRun::completeJournal);
    connect(&m_writing, &QFutureWatcher<WriteOutcome>::finished, this, &DownloadRun::onWritten);
}

DownloadRun::~DownloadRun()
{
    // A write on its way still finishes in the client's thread; nothing waits for it here.
    if (m_job)
        m_job->requestStop();
}

void DownloadRun::start(ScanOptions reading)
{
    if (m_stage != Stage::Idle)
        return;
    if (!m_client) {
        m_stage = Stage::Done;
        return emit failed(tr("no drive is connected; nothing was written"));
    }
    m_stage = Stage::Reading;
    m_driveAddress = reading.driveAddress;
    reading.values = true;
    reading.parameterList = false; // the password level and every value, to plan against
    m_reading.setFuture(m_client->scan(reading));
}

void DownloadRun::onRead()
{
    m_drive = m_reading.future().resultCount() ? m_reading.future().result() : DriveDescription{};
    if (m_stopped) {
        m_stage = Stage::Done;
        return emit failed(tr("stopped before anything was written"));
    }
    if (m_reading.future().resultCount() == 0 || !m_drive.incompleteReason.isEmpty()) {
        m_stage = Stage::Done;
        const QString reason = m_drive.incompleteReason.isEmpty() ? tr("no answer")
                                                                  : m_drive.incompleteReason;
        return emit failed(tr("the drive could not be read (%1); nothing was written").arg(reason));
    }
    m_stage = Stage::Planned;
    m_plan = planDownload(m_file, m_drive, m_options);
    emit planned(m_plan);
}

void DownloadRun::setOptions(const DownloadOptions &options)
{
    m_options = options;
    if (m_stage != Stage::Planned)
        return;
    m_plan = planDownload(m_file, m_drive, m_options);
    emit planned(m_plan);
}

void DownloadRun::write()
{
    if (m_stage != Stage::Planned || m_plan.isRefused())
        return;
    if (!m_client) {
        m_stage = Stage::Done;
        return emit failed(tr("the drive is no longer connected; nothing was written"));
    }
    // The first item's entries are stored before anything is sent, the others' while it is
    // written: the job holds each item back until its entries are stored, and the first
    // telegram does not wait for the journal to take them all.
    const auto items = int(m_plan.items.size());
    const int first = m_journal ? std::min(1, items) : items;
    // Only the journal's own failure may stop the download after its first item: what the
    // plan cannot journal refuses it before anything is sent.
    const auto undescribed = std::find_if(m_plan.items.cbegin(), m_plan.items.cend(),
                                          [this](const DownloadItem &i) { return !parameterOf(i); });
    QString error;
    if (m_journal && undescribed != m_plan.items.cend())
        error = tr("%1 is not described").arg(undescribed->id);
    if (!error.isEmpty() || (m_journal && !beginJournal(0, first, &error))) {
        m_stage = Stage::Done;
        return emit failed(
            tr("the journal cannot record the download: %1; nothing was written").arg(error));
    }
    m_stage = Stage::Writing;
    QList<ValueChange> changes;
    QList<WriteOrder> order;
    for (const DownloadItem &item : std::as_const(m_plan.items)) {
        changes << item.change;
        order << item.order;
    }
    m_job = std::make_shared<WriteChangesJob>(m_protocol, changes, order);
    m_job->release(first);
    m_writing.setFuture(m_client->run(m_job, m_driveAddress));
    if (first == items)
        return;
    if (beginJournal(first, items, &error)) {
        m_job->release(items);
    } else {
        // What was sent is journaled; nothing more goes out.
        m_journalError = tr("the journal cannot record the download: %1").arg(error);
        m_journaled.resize(items);
        m_job->requestStop();
    }
    m_client->resume(m_job);
}

const ParameterDescription *DownloadRun::parameterOf(const DownloadItem &item) const
{
    // The plan writes what the drive described; a forced download may write what only the
    // file describes.
    const ParameterDescription *parameter = m_drive.find(item.change.address);
    return parameter ? parameter : m_file.find(item.change.address);
}

bool DownloadRun::beginJournal(int begin, int end, QString *error)
{
    if (begin == end)
        return true; // nothing written, no job in the journal
    QList<EditJournal::Write> writes;
    for (int index = begin; index < end; ++index) {
        const DownloadItem &item = m_plan.items.at(index);
        EditJournal::Write write { item.id, parameterOf(item), item.change.steps, item.before };
        for (WriteStep &step : write.steps)
            step.setMask = SetList::setsWritten(item.change.setProgrammable, step.setMask);
        writes << write;
    }
    // The drive of the bus this run writes to, which need not be the connection's own.
    ConnectionSettings settings = m_client->settings();
    if (m_driveAddress >= 0)
        settings.driveAddress = m_driveAddress;
    const std::optional<QList<QList<EditJournal::Entry>>> begun
        = m_journal->begin(EditJournal::driveOf(settings, m_drive), writes, error);
    if (!begun)
        return false;
    m_journaled << *begun;
    return true;
}

void DownloadRun::completeJournal(int begin, int end)
{
    if (m_journaled.isEmpty())
        return;
    const QFuture<WriteOutcome> future = m_writing.future();
    m_journal->completeTogether([&] {
        for (int index = begin; index < end && index < int(m_journaled.size()); ++index) {
            m_journal->complete(*parameterOf(m_plan.items.at(index)), m_journaled.at(index),
                                future.resultAt(index));
            m_journaled[index].clear(); // completed
        }
    });
}

void DownloadRun::stop()
{
    m_stopped = true;
    if (m_stage == Stage::Reading && m_client)
        m_client->stopScan();
    else if (m_stage == Stage::Writing && m_job)
        m_job->requestStop();
}

void DownloadRun::onWritten()
{
    const QFuture<WriteOutcome> future = m_writing.future();
    QList<std::optional<WriteOutcome>> outcomes(m_plan.items.size());
    QString stopReason;
    for (int i = 0; i < int(outcomes.size()); ++i) {
        if (!future.isResultReadyAt(i))
            continue;
        outcomes[i] = future.resultAt(i);
        // A change whose writes were answered may have lost its read-back.
        // Said as the request that found the connection gone says it ("the drive stopped
        // answering"), not as an earlier failure of the same change.
        if (outcomes[i]->connectionFailed) {
            stopReason = !outcomes[i]->connectionError.isEmpty() ? outcomes[i]->connectionError
                : outcomes[i]->error.isEmpty()                   ? outcomes[i]->readBackError
                                                                 : outcomes[i]->error;
        }
    }
    if (m_stopped)
        stopReason = tr("stopped by the user");
    else if (!m_journalError.isEmpty())
        stopReason = m_journalError;
    if (m_journal && !m_journaled.isEmpty()) {
        // An item without an outcome was never sent: the drive holds what it held.
        m_journal->completeTogether([&] {
            for (int i = 0; i < int(outcomes.size()); ++i) {
                if (m_journaled.at(i).isEmpty())
                    continue;
                const DownloadItem &item = m_plan.items.at(i);
                if (outcomes[i]) {
                    m_journal->complete(*parameterOf(item), m_journaled.at(i), *outcomes[i]);
                    continue;
                }
                quint8 mask = 0;
                for (const WriteStep &step : item.change.steps)
                    mask |= step.setMask ? SetList::setsWritten(item.change.setProgrammable,
                                                                step.setMask)
                                         : quint8(1);
                m_journal->complete(
                    *parameterOf(item), m_journaled.at(i),
                    EditJournal::notSent(item.change.address, mask,
                                         stopReason.isEmpty() ? tr("the download ended first")
                                                              : stopReason));
            }
        });
        m_journaled.clear();
    }
    m_job.reset();
    m_stage = Stage::Done;
    emit finished(reportDownload(m_plan, outcomes, stopReason, m_drive));
}

} // namespace DriveDesk
