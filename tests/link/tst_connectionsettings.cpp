#include "link/ConnectionSettings.h"
#include "link/TcpTarget.h"

#include <QTest>

using namespace DriveDesk;

// Connection targets as the command line and the dialog give them, and the character format.
class TestConnectionSettings : public QObject
{
    Q_OBJECT
private slots:
    void parsesTcpTarget()
    {
        ConnectionSettings settings;
        QString error;
        QVERIFY2(settings.parseTarget(QStringLiteral("tcp:192.168.0.7:4001"), &error),
                 qPrintable(error));
        QCOMPARE(settings.kind, ConnectionSettings::Kind::Tcp);
        QCOMPARE(settings.host, QStringLiteral("192.168.0.7"));
        QCOMPARE(settings.port, quint16(4001));
        QCOMPARE(settings.target(), QStringLiteral("tcp:192.168.0.7:4001"));
    }

    void aServerWritesItsAddressAsTheClientDoes()
    {
        // drivedesk-sim --listen and --connect share one syntax; a server may ask for port 0.
        const std::optional<TcpTarget> any
            = TcpTarget::parse(QStringLiteral("[::1]:0"), TcpTarget::Port::AnyFree);
        QVERIFY(any);
        QCOMPARE(any->host, QStringLiteral("::1"));
        QCOMPARE(any->port, quint16(0));
        QString error;
        QVERIFY(!TcpTarget::parse(QStringLiteral("[::1]:0"), TcpTarget::Port::Given, &error));
        QVERIFY2(error.contains(QStringLiteral("1..65535")), qPrintable(error));
        QVERIFY(!TcpTarget::parse(QStringLiteral("host:70000"), TcpTarget::Port::AnyFree, &error));
        QVERIFY2(error.contains(QStringLiteral("0 picks a free one")), qPrintable(error));
        ConnectionSettings settings;
        QVERIFY(settings.parseTarget(QStringLiteral("tcp:[::1]:5020"), nullptr));
        QCOMPARE(settings.host, TcpTarget::parse(QStringLiteral("[::1]:5020"),
                                                 TcpTarget::Port::Given)->host);
    }

    void parsesIpv6AndHostNames()
    {
        ConnectionSettings settings;
        QString error;
        QVERIFY2(settings.parseTarget(QStringLiteral("tcp:[::1]:5020"), &error), qPrintable(error));
        QCOMPARE(settings.host, QStringLiteral("::1"));
        QCOMPARE(settings.target(), QStringLiteral("tcp:[::1]:5020"));
        QVERIFY2(settings.parseTarget(QStringLiteral("TCP:moxa.local:950"), &error),
                 qPrintable(error));
        QCOMPARE(settings.host, QStringLiteral("moxa.local"));
        QCOMPARE(settings.port, quint16(950));
    }

    void parsesSerialAndSimulated()
    {
        ConnectionSettings settings;
        QString error;
        QVERIFY(settings.parseTarget(QStringLiteral("serial:/dev/ttyUSB0"), &error));
        QCOMPARE(settings.kind, ConnectionSettings::Kind::Serial);
        QCOMPARE(settings.device, QStringLiteral("/dev/ttyUSB0"));
        QVERIFY(settings.parseTarget(QStringLiteral("serial:COM3"), &error));
        QCOMPARE(settings.device, QStringLiteral("COM3"));
        QVERIFY(settings.parseTarget(QStringLiteral("sim"), &error));
        QCOMPARE(settings.kind, ConnectionSettings::Kind::Simulated);
        QCOMPARE(settings.target(), QStringLiteral("sim"));
    }

    void rejectsBadTargetsWithReasonAndKeepsSettings_data()
    {
        QTest::addColumn<QString>("target");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown scheme") << "modbus:1" << "tcp:HOST:PORT";
        QTest::newRow("no port") << "tcp:localhost" << "no port";
        QTest::newRow("port zero") << "tcp:localhost:0" << "\"0\"";
        QTest::newRow("port too big") << "tcp:localhost:70000" << "70000";
        QTest::newRow("port not a number") << "tcp:localhost:abc" << "abc";
        QTest::newRow("no host") << "tcp::4001" << "host";
        QTest::newRow("no device") << "serial:" << "serial device";
        QTest::newRow("empty") << "" << "unknown connection";
        QTest::newRow("sim with address") << "sim:1" << "sim";
    }

    void rejectsBadTargetsWithReasonAndKeepsSettings()
    {
        QFETCH(QString, target);
        QFETCH(QString, mentions);
        ConnectionSettings settings;
        QVERIFY(settings.parseTarget(QStringLiteral("tcp:10.0.0.1:4001"), nullptr));
        QString error;
        QVERIFY(!settings.parseTarget(target, &error));
        QVERIFY2(error.contains(mentions), qPrintable(error));
        QCOMPARE(settings.target(), QStringLiteral("tcp:10.0.0.1:4001"));
    }

    void characterFormatFollowsProtocol()
    {
        ConnectionSettings settings;
        settings.protocol = Protocol::Hsp5;
        QCOMPARE(settings.effectiveDataBits(), QSerialPort::Data8);
        QCOMPARE(settings.effectiveParity(), QSerialPort::EvenParity);
        QCOMPARE(settings.effectiveStopBits(), QSerialPort::OneStop);
        settings.protocol = Protocol::Din66019II;
        QCOMPARE(settings.effectiveDataBits(), QSerialPort::Data7);
        settings.protocol = Protocol::Din66019;
        QCOMPARE(settings.effectiveDataBits(), QSerialPort::Data7);
        QCOMPARE(settings.effectiveParity(), QSerialPort::EvenParity);
        settings.dataBits = QSerialPort::Data8;
        settings.parity = QSerialPort::NoParity;
        settings.stopBits = QSerialPort::TwoStop;
        QCOMPARE(settings.effectiveDataBits(), QSerialPort::Data8);
        QCOMPARE(settings.effectiveParity(), QSerialPort::NoParity);
        QCOMPARE(settings.effectiveStopBits(), QSerialPort::TwoStop);
    }

    void displayNameSaysWhatAndWhere()
    {
        ConnectionSettings settings;
        QVERIFY(settings.parseTarget(QStringLiteral("serial:/dev/ttyUSB0"), nullptr));
        settings.protocol = Protocol::Din66019II;
        settings.driveAddress = 3;
        settings.baudRate = 19200;
        QCOMPARE(settings.displayName(),
                 QStringLiteral("DIN66019II drive 3 on /dev/ttyUSB0 (19200 7E1)"));
        settings.protocol = Protocol::Hsp5;
        QVERIFY(settings.parseTarget(QStringLiteral("tcp:127.0.0.1:4001"), nullptr));
        QCOMPARE(settings.displayName(), QStringLiteral("HSP5 via 127.0.0.1:4001"));
        QVERIFY(settings.parseTarget(QStringLiteral("sim"), nullptr));
        QCOMPARE(settings.displayName(), QStringLiteral("simulated HSP5 drive"));
    }
};

QTEST_GUILESS_MAIN(TestConnectionSettings)
#include "tst_connectionsettings.moc"
