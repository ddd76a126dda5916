#pragma once

#include "link/ConnectionSettings.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QCoreApplication>

#include <optional>

namespace DriveDesk {

// The connection options drivedesk and drivedesk-cli share (--connect, --protocol, --address,
// --baud, --language), so that both read and check them the same way.
class ConnectionOptions
{
    Q_DECLARE_TR_FUNCTIONS(ConnectionOptions)
public:
    void addTo(QCommandLineParser &parser) const;

    bool hasTarget(const QCommandLineParser &parser) const { return parser.isSet(m_connect); }
    // --protocol, --address, --baud or --hsp5-extensions: they only mean something with
    // --connect.
    bool hasTargetDetails(const QCommandLineParser &parser) const;

    // --language en|de; nothing when absent. False, with *error, for anything else.
    bool language(const QCommandLineParser &parser, std::optional<Language> *language,
                  QString *error) const;
    // The drive --connect names, with the other options applied. False, with *error naming the
    // bad option, when they make no sense.
    bool settings(const QCommandLineParser &parser, ConnectionSettings *settings,
                  QString *error) const;

    // An integer option within low..high; true and *value untouched when it is absent.
    static bool integer(const QCommandLineParser &parser, const QCommandLineOption &option,
                        qint64 low, qint64 high, qint64 *value, QString *error);
    static bool integer(const QCommandLineParser &parser, const QCommandLineOption &option,
                        int low, int high, int *value, QString *error);

private:
    QCommandLineOption m_connect{QStringLiteral("connect"), {}, QStringLiteral("target")};
    QCommandLineOption m_protocol{QStringLiteral("protocol"), {}, QStringLiteral("name")};
    QCommandLineOption m_address{QStringLiteral("address"), {}, QStringLiteral("n")};
    QCommandLineOption m_baud{QStringLiteral("baud"), {}, QStringLiteral("n")};
    QCommandLineOption m_language{QStringLiteral("language"), {}, QStringLiteral("lang")};
    QCommandLineOption m_hsp5Extensions{QStringLiteral("hsp5-extensions")};
};

} // namespace DriveDesk
