#include "link/TcpLink.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

using namespace DriveDesk;

namespace {

ConnectionSettings tcpSettings(quint16 port, const QString &host = QStringLiteral("127.0.0.1"))
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Tcp;
    settings.host = host;
    settings.port = port;
    return settings;
}

// A port on which nothing listens: taken, then given back.
quint16 closedPort()
{
    QTcpServer server;
    server.listen(QHostAddress::LocalHost, 0);
    return server.serverPort();
}

} // namespace

// TcpLink to a serial device server: the raw stream, and failures reported at once.
class TestTcpLink : public QObject
{
    Q_OBJECT
private slots:
    void carriesBytesBothWays()
    {
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        TcpLink link(tcpSettings(server.serverPort()));
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        QVERIFY(link.isOpen());
        QTRY_VERIFY(server.hasPendingConnections());
        QTcpSocket *peer = server.nextPendingConnection();

        const QByteArray request = QByteArrayLiteral("\x10\x00\x20\x00\x20\x10");
        link.send(request);
        QTRY_COMPARE(peer->bytesAvailable(), qint64(request.size()));
        QCOMPARE(peer->readAll(), request);

        QByteArray got;
        connect(&link, &Link::received, this, [&](const QByteArray &bytes) { got += bytes; });
        peer->write(QByteArrayLiteral("\x10\x80\x00\x00\x00\x46\x00\xD6"));
        QTRY_COMPARE(got, QByteArrayLiteral("\x10\x80\x00\x00\x00\x46\x00\xD6"));
        QCOMPARE(failed.count(), 0);
        QCOMPARE(link.description(), QStringLiteral("tcp 127.0.0.1:%1").arg(server.serverPort()));
    }

    void refusedConnectionFailsWithReason()
    {
        const quint16 port = closedPort();
        TcpLink link(tcpSettings(port));
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(failed.count(), 1);
        const QString reason = failed.at(0).at(0).toString();
        QVERIFY2(reason.contains(QStringLiteral("127.0.0.1:%1").arg(port)), qPrintable(reason));
        QVERIFY2(reason.contains(QStringLiteral("refused"), Qt::CaseInsensitive),
                 qPrintable(reason));
        QVERIFY(!link.isOpen());
    }

    void silentHostTimesOut()
    {
        // A non-routable address: the connection attempt hangs until the link gives up.
        TcpLink link(tcpSettings(4001, QStringLiteral("10.255.255.1")));
        link.setConnectTimeoutMs(200);
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_VERIFY_WITH_TIMEOUT(failed.count() + opened.count() > 0, 5000);
        if (opened.count() > 0)
            QSKIP("this network answers every address; no silent host to time out against");
        const QString reason = failed.at(0).at(0).toString();
        // Without a network the attempt fails at once instead; either way it says why.
        QVERIFY2(reason.contains(QStringLiteral("200 ms"))
                     || reason.contains(QStringLiteral("unreachable"), Qt::CaseInsensitive)
                     || reason.contains(QStringLiteral("network"), Qt::CaseInsensitive),
                 qPrintable(reason));
    }

    void serverClosingFailsPromptly()
    {
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        TcpLink link(tcpSettings(server.serverPort()));
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        QTRY_VERIFY(server.hasPendingConnections());
        QTcpSocket *peer = server.nextPendingConnection();
        peer->close();
        QTRY_COMPARE(failed.count(), 1);
        QVERIFY2(failed.at(0).at(0).toString().contains(QStringLiteral("closed the connection")),
                 qPrintable(failed.at(0).at(0).toString()));
        QVERIFY(!link.isOpen());
        // Reported once: the link opens again, and nothing of the old connection came between.
        link.open();
        QTRY_COMPARE(opened.count(), 2);
        QCOMPARE(failed.count(), 1);
    }

    void closeIsQuiet()
    {
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        TcpLink link(tcpSettings(server.serverPort()));
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        QTRY_VERIFY(server.hasPendingConnections());
        QTcpSocket *peer = server.nextPendingConnection();
        QSignalSpy peerGone(peer, &QTcpSocket::disconnected);
        link.close();
        QVERIFY(!link.isOpen());
        // The server sees the connection end only after the link's side of it has ended.
        QTRY_COMPARE(peerGone.count(), 1);
        QCOMPARE(failed.count(), 0);
    }

    void missingHostFailsWithReason()
    {
        TcpLink link(tcpSettings(0, QString()));
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(failed.count(), 1);
        QVERIFY(failed.at(0).at(0).toString().contains(QStringLiteral("no host or port")));
    }
};

QTEST_GUILESS_MAIN(TestTcpLink)
#include "tst_tcplink.moc"
