#include "UploadRun.h"

#include "parameters/ParameterDocument.h"
#include "parameters/ParameterList.h"

namespace DriveDesk {

namespace {

UploadGap driveGap(const QString &reason)
{
    return UploadGap { {}, {}, reason };
}

// The sets a parameter has whose value is missing: none when every value was read.
QStringList setsWithoutValue(const ParameterDescription &parameter)
{
    QStringList sets;
    const int count = parameter.isSetProgrammable() ? kParameterSets : 1;
    for (int set = 0; set < count; ++set) {
        if (!parameter.values[std::size_t(set)])
            sets << QString::number(set);
    }
    return sets;
}

} // namespace

QString UploadResult::summary() const
{
    switch (outcome) {
    case Outcome::Complete:
        return {};
    case Outcome::Cancelled:
        return tr("the upload was cancelled; nothing was saved");
    case Outcome::Refused:
        break;
    }
    int parameters = 0;
    for (const UploadGap &gap : missing)
        parameters += gap.id.isEmpty() ? 0 : 1;
    if (parameters == 0 || (!missing.isEmpty() && missing.constFirst().id.isEmpty())) {
        const QString reason = missing.isEmpty() ? tr("no answer") : missing.constFirst().reason;
        return tr("the drive could not be read to the end (%1); nothing was saved").arg(reason);
    }
    return tr("%n parameter(s) of the drive could not be read; nothing was saved", nullptr,
              parameters);
}

QStringList UploadResult::details() const
{
    QStringList lines;
    for (const UploadGap &gap : missing) {
        if (gap.id.isEmpty())
            lines << gap.reason;
        else if (gap.name.isEmpty())
            lines << tr("%1: %2").arg(gap.id, gap.reason);
        else
            lines << tr("%1 %2: %3").arg(gap.id, gap.name, gap.reason);
    }
    return lines;
}

UploadResult checkUpload(const DriveDescription &read)
{
    UploadResult result;
    result.document = read;
    if (!read.incompleteReason.isEmpty())
        result.missing << driveGap(read.incompleteReason);
    for (const GroupDescription &group : read.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            // What a list does not read holds its default (ParameterList::fromScan). A value
            // the drive changes by itself is no setting a download restores: where it could
            // not be confirmed, the file keeps the parameter with its error.
            if (!ParameterList::isReadByUpload(parameter)
                || ParameterProperties(parameter.properties1, parameter.properties2)
                       .isChangedByInverter())
                continue;
            const QString id = parameterId(group, parameter);
            if (!parameter.error.isEmpty()) {
                result.missing << UploadGap { id, parameter.name, parameter.error };
                continue;
            }
            const QStringList sets = setsWithoutValue(parameter);
            if (!sets.isEmpty()) {
                result.missing << UploadGap { id, parameter.name,
                                              UploadResult::tr("no value read for set(s) %1",
                                                               nullptr, int(sets.size()))
                                                  .arg(sets.join(QStringLiteral(", "))) };
            }
        }
    }
    result.outcome = result.missing.isEmpty() ? UploadResult::Outcome::Complete
                                              : UploadResult::Outcome::Refused;
    return result;
}

bool saveUpload(const QString &path, const UploadResult &result, QString *error)
{
    if (!result.isComplete()) {
        if (error)
            *error = result.summary();
        return false;
    }
    return ParameterDocument::save(path, result.document, error);
}

UploadRun::UploadRun(DriveClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    // Each answer moves the text if not the value: a silent drive is noticed at the first.
    const auto moved = [this] {
        if (m_client && m_client->isDriveSilent())
            return onSilent();
        emit progress(m_reading.progressValue(), m_reading.progressMaximum(),
                      m_reading.progressText());
    };
    connect(&m_reading, &QFutureWatcher<DriveDescription>::progressValueChanged, this, moved);
    connect(&m_reading, &QFutureWatcher<DriveDescription>::progressTextChanged, this, moved);
    connect(&m_reading, &QFutureWatcher<DriveDescription>::finished, this, &UploadRun::onRead);
    if (m_client)
        connect(m_client, &DriveClient::driveSilentChanged, this, [this](bool silent) {
            if (silent)
                onSilent();
        });
}

UploadRun::~UploadRun()
{
    m_reading.disconnect(this);
    if (m_running)
        m_reading.cancel();
}

void UploadRun::start(ScanOptions reading)
{
    if (m_running)
        return;
    m_cancelled = false;
    m_silent = false;
    if (!m_client || m_client->state() != DriveClient::State::Connected) {
        UploadResult result;
        result.missing << driveGap(tr("no drive is connected"));
        return emit finished(result);
    }
    // How to read (metadata source, cache, identification text) is the caller's; what to
    // read is the upload's.
    ScanOptions options = reading;
    options.groupPages.clear();
    options.onlyParameters.clear();
    options.values = true;
    options.plaintexts = true;
    options.parameters = true;
    options.parameterList = true;
    m_running = true;
    m_reading.setFuture(m_client->scan(options));
}

void UploadRun::cancel()
{
    if (!m_running)
        return;
    m_cancelled = true;
    m_reading.cancel();
}

void UploadRun::onSilent()
{
    // Every read after this one would wait out its timeouts for nothing: a value missing
    // already makes the backup incomplete.
    if (!m_running || m_silent || m_cancelled)
        return;
    m_silent = true;
    m_reading.cancel();
}

void UploadRun::onRead()
{
    if (!m_running)
        return;
    const QFuture<DriveDescription> future = m_reading.future();
    UploadResult result;
    if (m_cancelled) {
        result.outcome = UploadResult::Outcome::Cancelled;
    } else if (m_silent) {
        result.missing << driveGap(
            tr("the drive stopped answering during the read (no answer after every attempt)"));
    } else if (future.isCanceled() || future.resultCount() == 0) {
        result.missing << driveGap(m_client ? tr("the read ended without a result")
                                            : tr("the connection was closed"));
    } else {
        result = checkUpload(future.result());
    }
    end(result);
}

void UploadRun::end(const UploadResult &result)
{
    m_running = false;
    emit finished(result);
}

} // namespace DriveDesk
