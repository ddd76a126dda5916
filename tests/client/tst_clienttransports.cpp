#include "ClientTestSupport.h"

#include "bus/BusClock.h"
#include "bus/SimulatedBus.h"
#include "bus/SimulatorServer.h"

#include <QFileInfo>
#include <QProcess>
#include <QSerialPort>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

Q_DECLARE_METATYPE(DriveDesk::Protocol)

namespace {

// A simulated drive that answers on a serial device, as a real drive on a real port would.
class SerialDrive : public QObject
{
public:
    SerialDrive(const QString &device, Protocol protocol)
        : m_bus(protocol, fast())
        , m_clock(&m_bus)
    {
        m_port.setPortName(device);
        connect(&m_port, &QSerialPort::readyRead, this,
                [this] { m_clock.receive(m_port.readAll()); });
        connect(&m_clock, &BusClock::transmit, this, [this](const QByteArray &bytes) {
            m_port.write(bytes);
        });
    }

    bool open() { return m_port.open(QIODevice::ReadWrite); }
    QString error() const { return m_port.errorString(); }

private:
    SimulatedBus m_bus;
    BusClock m_clock;
    QSerialPort m_port;
};

ConnectionSettings serial(const QString &device, Protocol protocol)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Serial;
    settings.device = device;
    settings.protocol = protocol;
    return settings;
}

void checkRoundTrips(const Session &s)
{
    const Reply read = s.call(s.client->readValue(kMaxSpeedForward, 1));
    QVERIFY2(read.ok(), qPrintable(describeReply(read)));
    QCOMPARE(read.data<ParameterValue>()->value, kMaxSpeedDefault);
    QVERIFY(s.call(s.client->writeValue(kMaxSpeedForward, 2750, 1)).ok());
    QCOMPARE(valueOf(s.call(s.client->readValue(kMaxSpeedForward, 1))), 2750);
    const Reply name = s.request(Service::ParameterName, Access::Read,
                                 NameData{kMaxSpeedForward, 0, {}});
    QCOMPARE(name.data<NameData>()->text, QByteArrayLiteral("Maximum speed forward"));
    QCOMPARE(s.call(s.client->writeValue(kRatedCurrent, 1, 1)).ack(), Ack::WriteProtected);
}

} // namespace

// The same client over the links that leave the process: TCP to a device server and a serial
// port (a pseudo-terminal, through QSerialPort).
class TestClientTransports : public QObject
{
    Q_OBJECT
private:
    static void protocols()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }

private slots:
    void overTcp_data() { protocols(); }
    void overTcp()
    {
        QFETCH(Protocol, protocol);
        SimulatorServer server(protocol, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Tcp;
        settings.host = QStringLiteral("127.0.0.1");
        settings.port = server.tcpPort();
        settings.protocol = protocol;
        Session s(settings);
        QVERIFY(s.connected());
        checkRoundTrips(s);
    }

    void overTheSimulatorsPseudoTerminal_data() { protocols(); }
    void overTheSimulatorsPseudoTerminal()
    {
        QFETCH(Protocol, protocol);
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("drive"));
        SimulatorServer server(protocol, fast());
        QString error;
        QVERIFY2(server.listenPty(link, &error), qPrintable(error));
        Session s(serial(link, protocol));
        QVERIFY(s.connected());
        checkRoundTrips(s);
    }

    void overASocatPseudoTerminalPair_data() { protocols(); }
    void overASocatPseudoTerminalPair()
    {
        QFETCH(Protocol, protocol);
        const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
        if (socat.isEmpty())
            QSKIP("socat is not installed");
        QTemporaryDir dir;
        const QString driveEnd = dir.filePath(QStringLiteral("A"));
        const QString clientEnd = dir.filePath(QStringLiteral("B"));
        QProcess pair;
        pair.start(socat, {QStringLiteral("pty,raw,echo=0,link=") + driveEnd,
                           QStringLiteral("pty,raw,echo=0,link=") + clientEnd});
        QVERIFY(pair.waitForStarted());
        QTRY_VERIFY(QFileInfo::exists(driveEnd) && QFileInfo::exists(clientEnd));

        SerialDrive drive(driveEnd, protocol);
        QVERIFY2(drive.open(), qPrintable(drive.error()));
        {
            Session s(serial(clientEnd, protocol));
            QVERIFY(s.connected());
            checkRoundTrips(s);
        }
        pair.terminate();
        QVERIFY(pair.waitForFinished());
    }
};

QTEST_GUILESS_MAIN(TestClientTransports)
#include "tst_clienttransports.moc"
