#include "BusTestSupport.h"
#include "bus/SimulatedBus.h"
#include "bus/SimulatorServer.h"

#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::BusTest;

namespace {

SimulationOptions options(QList<int> addresses = {1})
{
    SimulationOptions o;
    o.driveAddresses = addresses;
    o.replyLatencyUs = 100;
    return o;
}

// A raw TCP client: sends requests and collects the answer while the event loop runs, until
// `expected` bytes are in.
QByteArray ask(QTcpSocket &socket, const QByteArray &requests, qsizetype expected)
{
    socket.readAll();
    socket.write(requests);
    QByteArray answer;
    const auto collect = [&] {
        answer += socket.readAll();
        return answer.size() >= expected;
    };
    if (!QTest::qWaitFor(collect, 2000))
        qWarning("%d of %d bytes came", int(answer.size()), int(expected));
    collect();
    return answer;
}

} // namespace

// SimulatorServer: one operator at a time over TCP, drive state kept, pty link handling.
class TestSimulatorServer : public QObject
{
    Q_OBJECT
private slots:
    void reportsWhereItListens()
    {
        SimulatorServer server(Protocol::Hsp5, options());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        QVERIFY(server.tcpPort() != 0);
        const QString expected = QStringLiteral("tcp:127.0.0.1:%1").arg(server.tcpPort());
        QCOMPARE(server.addresses(), QStringList{expected});
    }

    void rejectsBadListenAddress()
    {
        SimulatorServer server(Protocol::Hsp5, options());
        QString error;
        QVERIFY(!server.listenTcp(QStringLiteral("not-an-ip"), 0, &error));
        QVERIFY2(error.contains(QStringLiteral("not-an-ip")), qPrintable(error));
    }

    void refusesASecondOperatorAndKeepsTheFirst()
    {
        SimulatorServer server(Protocol::Hsp5, options());
        QVERIFY(server.listenTcp(QStringLiteral("127.0.0.1"), 0, nullptr));
        QSignalSpy connected(&server, &SimulatorServer::clientConnected);
        QSignalSpy refused(&server, &SimulatorServer::connectionRefused);
        QTcpSocket first;
        first.connectToHost(QStringLiteral("127.0.0.1"), server.tcpPort());
        QVERIFY(first.waitForConnected(1000));
        QTRY_COMPARE(connected.count(), 1);

        QTcpSocket second;
        QSignalSpy secondGone(&second, &QTcpSocket::disconnected);
        second.connectToHost(QStringLiteral("127.0.0.1"), server.tcpPort());
        QTRY_COMPARE(refused.count(), 1);
        QTRY_COMPARE(secondGone.count(), 1);

        Operator op(Protocol::Hsp5);
        const QByteArray answer = ask(first, op.encode(readValue(kStateAddress, 1)), 8);
        const QList<Telegram> replies = op.telegrams(answer);
        QCOMPARE(replies.size(), 1);
        QVERIFY(server.hasClient());
    }

    void drivesKeepStateAcrossConnections()
    {
        SimulatorServer server(Protocol::Din66019II, options({1, 2}));
        QVERIFY(server.listenTcp(QStringLiteral("127.0.0.1"), 0, nullptr));
        QSignalSpy disconnected(&server, &SimulatorServer::clientDisconnected);
        Operator op(Protocol::Din66019II);
        {
            QTcpSocket socket;
            socket.connectToHost(QStringLiteral("127.0.0.1"), server.tcpPort());
            QVERIFY(socket.waitForConnected(1000));
            QCOMPARE(ask(socket, op.encode(writeValue(kWritableAddress, 123, 1, 2)), 2),
                     QByteArrayLiteral("1\x06"));
            socket.disconnectFromHost();
        }
        QTRY_COMPARE(disconnected.count(), 1);
        QTcpSocket socket;
        socket.connectToHost(QStringLiteral("127.0.0.1"), server.tcpPort());
        QVERIFY(socket.waitForConnected(1000));
        // A new operator starts without a selection: the drive answers only the request that
        // selects it, the second one.
        const QByteArray answer = ask(socket,
                                      op.encode(readValue(kWritableAddress, 2))
                                          + op.encode(readValue(kWritableAddress, 3, 2)),
                                      13);
        const QList<Telegram> replies = op.telegrams(answer);
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].operatorInvoke, quint8(3));
        QCOMPARE(replies[0].as<ParameterValue>()->value, 123);
    }

    void ptyLinkComesAndGoes()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("drive"));
        {
            SimulatorServer server(Protocol::Hsp5, options());
            QString error;
            QVERIFY2(server.listenPty(path, &error), qPrintable(error));
            QVERIFY(QFileInfo(path).isSymLink());
            QCOMPARE(QFileInfo(path).symLinkTarget(), server.ptyDevice());
            QCOMPARE(server.addresses(), QStringList{QStringLiteral("pty:") + path});
            server.close();
            QVERIFY(!QFileInfo(path).isSymLink());
            QVERIFY2(server.listenPty(path, &error), qPrintable(error));
        }
        // Shut down by destruction: the link goes too.
        QVERIFY(!QFileInfo(path).isSymLink());
    }

    void ptyReplacesAStaleLinkButNotAFile()
    {
        QTemporaryDir dir;
        const QString stale = dir.filePath(QStringLiteral("stale"));
        QVERIFY(QFile::link(dir.filePath(QStringLiteral("gone")), stale));
        SimulatorServer server(Protocol::Hsp5, options());
        QString error;
        QVERIFY2(server.listenPty(stale, &error), qPrintable(error));
        server.close();

        const QString file = dir.filePath(QStringLiteral("file"));
        QFile existing(file);
        QVERIFY(existing.open(QIODevice::WriteOnly));
        existing.close();
        QVERIFY(!server.listenPty(file, &error));
        QVERIFY2(error.contains(QStringLiteral("already exists")), qPrintable(error));
        QVERIFY(QFileInfo(file).isFile());
    }
};

QTEST_GUILESS_MAIN(TestSimulatorServer)
#include "tst_simulatorserver.moc"
