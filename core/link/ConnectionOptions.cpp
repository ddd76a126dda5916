#include "ConnectionOptions.h"

namespace DriveDesk {

void ConnectionOptions::addTo(QCommandLineParser &parser) const
{
    parser.addOptions({m_connect, m_protocol, m_address, m_baud, m_language, m_hsp5Extensions});
}

bool ConnectionOptions::hasTargetDetails(const QCommandLineParser &parser) const
{
    return parser.isSet(m_protocol) || parser.isSet(m_address) || parser.isSet(m_baud)
           || parser.isSet(m_hsp5Extensions);
}

bool ConnectionOptions::integer(const QCommandLineParser &parser, const QCommandLineOption &option,
                                qint64 low, qint64 high, qint64 *value, QString *error)
{
    if (!parser.isSet(option))
        return true;
    bool ok = false;
    const qint64 n = parser.value(option).toLongLong(&ok);
    if (!ok || n < low || n > high) {
        *error = tr("--%1 %2: expected a number from %3 to %4")
                     .arg(option.names().constFirst(), parser.value(option))
                     .arg(low)
                     .arg(high);
        return false;
    }
    *value = n;
    return true;
}

bool ConnectionOptions::integer(const QCommandLineParser &parser, const QCommandLineOption &option,
                                int low, int high, int *value, QString *error)
{
    qint64 n = *value;
    if (!integer(parser, option, qint64(low), qint64(high), &n, error))
        return false;
    *value = int(n);
    return true;
}

bool ConnectionOptions::language(const QCommandLineParser &parser,
                                 std::optional<Language> *language, QString *error) const
{
    if (!parser.isSet(m_language))
        return true;
    const QString name = parser.value(m_language);
    *language = languageFromCode(name);
    if (!*language) {
        *error = tr("unknown language \"%1\": use en or de").arg(name);
        return false;
    }
    return true;
}

bool ConnectionOptions::settings(const QCommandLineParser &parser, ConnectionSettings *settings,
                                 QString *error) const
{
    ConnectionSettings result;
    if (!parser.isSet(m_connect)) {
        *error = tr("--connect is missing: give tcp:HOST:PORT, serial:DEVICE or sim");
        return false;
    }
    if (!result.parseTarget(parser.value(m_connect), error))
        return false;
    if (parser.isSet(m_protocol)) {
        const auto protocol = protocolFromName(parser.value(m_protocol));
        if (!protocol) {
            *error = tr("unknown protocol \"%1\": use hsp5, din66019ii or din66019")
                         .arg(parser.value(m_protocol));
            return false;
        }
        result.protocol = *protocol;
    }
    int baudRate = result.baudRate;
    // A serial line finds its rate unless told one; elsewhere the rate is the simulated
    // drive's or the device server's business.
    const bool automatic
        = !parser.isSet(m_baud)
          || parser.value(m_baud).compare(QLatin1String("auto"), Qt::CaseInsensitive) == 0;
    if (!integer(parser, m_address, 0, ConnectionSettings::kMaxDriveAddress, &result.driveAddress,
                 error)
        || (!automatic
            && !integer(parser, m_baud, ConnectionSettings::kMinimumBaudRate,
                        ConnectionSettings::kMaximumBaudRate, &baudRate, error)))
        return false;
    result.baudRate = baudRate;
    result.automaticBaudRate = automatic && result.kind == ConnectionSettings::Kind::Serial;
    if (parser.isSet(m_hsp5Extensions)) {
        if (result.protocol != Protocol::Hsp5) {
            *error = tr("--hsp5-extensions needs --protocol hsp5");
            return false;
        }
        // The simulated drive then has them too: it is the drive known to have them.
        result.hsp5Extensions = true;
        result.simulation.hsp5Extensions = true;
    }
    // The simulated drive answers where the options say a drive is.
    result.simulation.driveAddresses = {result.driveAddress};
    result.simulation.baudRate = baudRate;
    std::optional<Language> chosen;
    if (!language(parser, &chosen, error))
        return false;
    result.language = chosen.value_or(Language::English);
    *settings = result;
    return true;
}

} // namespace DriveDesk
