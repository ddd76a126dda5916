#include "link/ConnectionOptions.h"

#include <QTest>

using namespace DriveDesk;

namespace {

// The settings the command line gives, or nothing and *error.
std::optional<ConnectionSettings> parse(const QStringList &options, QString *error)
{
    QCommandLineParser parser;
    const ConnectionOptions connection;
    connection.addTo(parser);
    if (!parser.parse(QStringList { QStringLiteral("drivedesk-cli") } + options)) {
        *error = parser.errorText();
        return std::nullopt;
    }
    ConnectionSettings settings;
    if (!connection.settings(parser, &settings, error))
        return std::nullopt;
    return settings;
}

} // namespace

// --baud: a serial line finds its rate unless given one.
class TestConnectionOptions : public QObject
{
    Q_OBJECT
private slots:
    void aSerialLineFindsItsRateUnlessGivenOne()
    {
        QString error;
        const QStringList serial { QStringLiteral("--connect"),
                                   QStringLiteral("serial:/dev/ttyUSB0") };
        auto settings = parse(serial, &error);
        QVERIFY2(settings, qPrintable(error));
        QVERIFY(settings->automaticBaudRate);

        settings = parse(serial + QStringList { QStringLiteral("--baud"), QStringLiteral("auto") },
                         &error);
        QVERIFY2(settings, qPrintable(error));
        QVERIFY(settings->automaticBaudRate);

        settings = parse(serial + QStringList { QStringLiteral("--baud"), QStringLiteral("9600") },
                         &error);
        QVERIFY2(settings, qPrintable(error));
        QVERIFY(!settings->automaticBaudRate);
        QCOMPARE(settings->baudRate, 9600);

        settings = parse(serial + QStringList { QStringLiteral("--baud"), QStringLiteral("fast") },
                         &error);
        QVERIFY(!settings);
        QVERIFY2(error.contains(QStringLiteral("--baud fast")), qPrintable(error));
    }

    void otherLinksHaveNoSearch()
    {
        QString error;
        for (const char *target : { "tcp:127.0.0.1:5020", "sim" }) {
            const auto settings = parse({ QStringLiteral("--connect"), QString::fromLatin1(target),
                                          QStringLiteral("--baud"), QStringLiteral("auto") },
                                        &error);
            QVERIFY2(settings, qPrintable(error));
            QVERIFY(!settings->automaticBaudRate);
            QCOMPARE(settings->baudRate, 38400);
        }
    }
};

QTEST_GUILESS_MAIN(TestConnectionOptions)
#include "tst_connectionoptions.moc"
