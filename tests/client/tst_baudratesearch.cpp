#include "ClientTestSupport.h"

#include "bus/SimulatorServer.h"
#include "client/BaudRateSearch.h"

#include <QTemporaryDir>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

Q_DECLARE_METATYPE(DriveDesk::Protocol)

namespace {

ConnectionSettings serial(const QString &device, Protocol protocol, bool automatic)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Serial;
    settings.device = device;
    settings.protocol = protocol;
    settings.automaticBaudRate = automatic;
    return settings;
}

SimulationOptions at(qint32 baudRate)
{
    SimulationOptions options = fast();
    options.baudRate = baudRate;
    return options;
}

} // namespace

// The client finds the baud rate of a drive on a serial line by itself. The simulated drive on
// its pseudo-terminal hears only what comes at its own rate: the client's port setting reaches
// it through the pty's shared termios, so a wrong rate goes unanswered as on a real line.
class TestBaudRateSearch : public QObject
{
    Q_OBJECT
private slots:
    void theLikeliestRatesComeFirst()
    {
        const QList<qint32> hsp5 = BaudRateSearch::candidates(Protocol::Hsp5);
        QCOMPARE(hsp5.first(), 38400); // an HSP5 drive after power-on
        QVERIFY(hsp5.contains(19200) && hsp5.contains(9600) && hsp5.contains(115200));
        const QList<qint32> din = BaudRateSearch::candidates(Protocol::Din66019II);
        // Seed 003: typically 9600..38400.
        QCOMPARE(din.mid(0, 3), (QList<qint32> { 38400, 19200, 9600 }));
    }

    void findsTheDrivesRate_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<qint32>("rate");
        QTest::newRow("hsp5 19200") << Protocol::Hsp5 << 19200;
        QTest::newRow("hsp5 57600") << Protocol::Hsp5 << 57600;
        QTest::newRow("din66019ii 9600") << Protocol::Din66019II << 9600;
        QTest::newRow("din66019 19200") << Protocol::Din66019 << 19200;
    }

    void findsTheDrivesRate()
    {
        QFETCH(Protocol, protocol);
        QFETCH(qint32, rate);
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("drive"));
        SimulatorServer server(protocol, at(rate));
        QString error;
        QVERIFY2(server.listenPty(link, &error), qPrintable(error));

        DriveClient client(serial(link, protocol, true), everyLink());
        QSignalSpy found(&client, &DriveClient::baudRateFound);
        QSignalSpy failed(&client, &DriveClient::connectionFailed);
        client.connectToDrive();
        QTRY_VERIFY_WITH_TIMEOUT(
            client.state() == DriveClient::State::Connected || !failed.isEmpty(), kWaitMs);
        QVERIFY2(failed.isEmpty(), qPrintable(failed.value(0).value(0).toString()));
        QCOMPARE(found.size(), 1);
        QCOMPARE(found.first().at(0).value<qint32>(), rate);
        QCOMPARE(client.settings().baudRate, rate);
        QVERIFY2(client.settings().displayName().contains(QString::number(rate)),
                 qPrintable(client.settings().displayName()));
        // The rates tried before were set on the line, and the drive did not hear them.
        QVERIFY(server.ignoredAtOtherRates() > 0);

        const Reply read
            = replyOf(protocol == Protocol::Din66019 ? client.readValueStandard(kMaxSpeedForward, 0)
                                                     : client.readValue(kMaxSpeedForward, 1));
        QVERIFY2(read.ok(), qPrintable(read.message()));
    }

    void aFixedRateIsThatRate()
    {
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("drive"));
        SimulatorServer server(Protocol::Din66019II, at(19200));
        QString error;
        QVERIFY2(server.listenPty(link, &error), qPrintable(error));

        ConnectionSettings wrong = serial(link, Protocol::Din66019II, false);
        wrong.baudRate = 38400;
        {
            Session s(wrong);
            QVERIFY(s.connected()); // the port opens; the drive is not at this rate
            const Reply read = s.call(s.client->readValue(kMaxSpeedForward, 1));
            QCOMPARE(read.status, Reply::Status::Timeout);
        }
        ConnectionSettings right = wrong;
        right.baudRate = 19200;
        Session s(right);
        QVERIFY(s.connected());
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 1)).ok());
    }

    void noRateAnswersAndTheConnectionFails()
    {
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("drive"));
        SimulatorServer server(Protocol::Hsp5, at(4800)); // a rate no search tries
        QString error;
        QVERIFY2(server.listenPty(link, &error), qPrintable(error));

        DriveClient client(serial(link, Protocol::Hsp5, true), everyLink());
        QSignalSpy failed(&client, &DriveClient::connectionFailed);
        client.connectToDrive();
        QTRY_VERIFY_WITH_TIMEOUT(!failed.isEmpty(), kWaitMs);
        const QString reason = failed.first().at(0).toString();
        QVERIFY2(reason.contains(QStringLiteral("no drive answered at 38400, 19200, 9600")),
                 qPrintable(reason));
        QCOMPARE(client.state(), DriveClient::State::Disconnected);
    }
};

QTEST_GUILESS_MAIN(TestBaudRateSearch)
#include "tst_baudratesearch.moc"
