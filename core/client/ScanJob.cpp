#include "ScanJob.h"

#include "DriveScanner.h"

namespace DriveDesk {

ScanJob::ScanJob(ScanOptions options, const ConnectionSettings &settings,
                 std::function<QString()> connection, QObject *owner)
    : m_options(std::move(options))
    , m_settings(settings)
    , m_connection(std::move(connection))
    , m_owner(owner)
{
    promise().setProgressRange(0, 1000);
    // The switch that says the drive has DriveDesk's services also lets the scan ask service 13.
    m_options.identificationText = m_options.identificationText || m_settings.hsp5Extensions;
}

ScanJob::~ScanJob()
{
    // A scan that never finished (its client went first): its handlers point here.
    if (m_scanner) {
        m_scanner->disconnect();
        m_scanner->deleteLater();
    }
}

void ScanJob::start()
{
    m_scanner = new DriveScanner(sink(), m_options, m_settings.language, m_owner);
    QObject::connect(m_scanner, &DriveScanner::progress, m_scanner,
                     [this](int done, int total, const QString &what) {
                         // The total grows as the scan learns; the bar never runs backwards.
                         const int value = total > 0 ? int(qint64(done) * 1000 / total) : 0;
                         m_shownProgress = std::max(m_shownProgress, std::min(value, 999));
                         promise().setProgressValueAndText(m_shownProgress, what);
                     });
    QObject::connect(m_scanner, &DriveScanner::finished, m_scanner,
                     [this](const DriveDescription &found) { onFinished(found); });
    m_scanner->start();
}

void ScanJob::stopping()
{
    if (m_scanner)
        m_scanner->cancel();
}

void ScanJob::finishEarly()
{
    stopping();
}

void ScanJob::onFinished(const DriveDescription &found)
{
    // Done with it: it goes once its signal has unwound, while the client's thread still runs.
    m_scanner->deleteLater();
    m_scanner = nullptr;
    DriveDescription description = found;
    if (description.protocol.isEmpty())
        description.protocol = protocolName(m_settings.protocol);
    if (description.connection.isEmpty() && m_connection)
        description.connection = m_connection();
    if (description.driveAddress < 0 && m_settings.protocol != Protocol::Hsp5)
        description.driveAddress = m_settings.driveAddress;
    promise().setProgressValueAndText(1000, description.incompleteReason);
    promise().addResult(description);
    end();
}

} // namespace DriveDesk
