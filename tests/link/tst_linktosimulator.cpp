#include "bus/SimulatorServer.h"
#include "link/SerialLink.h"
#include "link/TcpLink.h"
#include "protocol/Codec.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;

namespace {

// Seed 000's worked example: service 0 read of 2000h set mask 20h, first operator cycle. The
// simulated F5 has no parameter there, so the reply is an error acknowledge of the same length.
const QByteArray kHsp5Request = QByteArrayLiteral("\x10\x00\x20\x00\x20\x10");

SimulationOptions options()
{
    SimulationOptions o;
    o.replyLatencyUs = 200;
    return o;
}

// Collects what a link receives and decodes it as the operator does.
struct Receiver {
    explicit Receiver(Link &link, Protocol protocol)
        : codec(makeCodec(protocol))
        , decoder(codec->makeDecoder(Role::Operator))
    {
        QObject::connect(&link, &Link::received, &link, [this](const QByteArray &bytes) {
            raw += bytes;
            decoder->feed(bytes);
            while (std::optional<Decoded> item = decoder->next()) {
                if (const auto *telegram = std::get_if<Telegram>(&*item))
                    telegrams.append(*telegram);
                else
                    errors.append(std::get<DecodeError>(*item).detail);
            }
        });
    }
    std::unique_ptr<ProtocolCodec> codec;
    std::unique_ptr<FrameDecoder> decoder;
    QByteArray raw;
    QList<Telegram> telegrams;
    QStringList errors;
};

} // namespace

// The real links against drivedesk's own simulator: over TCP and over its pseudo-terminal.
class TestLinkToSimulator : public QObject
{
    Q_OBJECT
private slots:
    void tcpLinkExchangesTelegrams()
    {
        SimulatorServer server(Protocol::Hsp5, options());
        QVERIFY(server.listenTcp(QStringLiteral("127.0.0.1"), 0, nullptr));
        ConnectionSettings settings;
        const QString target = QStringLiteral("tcp:127.0.0.1:%1").arg(server.tcpPort());
        QVERIFY(settings.parseTarget(target, nullptr));
        TcpLink link(settings);
        Receiver receiver(link, Protocol::Hsp5);
        QSignalSpy opened(&link, &Link::opened);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        link.send(kHsp5Request);
        QTRY_COMPARE(receiver.telegrams.size(), 1);
        const Telegram &reply = receiver.telegrams[0];
        QCOMPARE(receiver.raw.size(), 8); // a value response keeps its length, error or not
        QCOMPARE(quint8(receiver.raw[0]), quint8(0x10));
        QCOMPARE(quint8(receiver.raw[1]), quint8(0x80));
        QVERIFY(reply.isResponse());
        QCOMPARE(reply.operatorInvoke, quint8(1));
        QCOMPARE(reply.service, Service::ParameterValue);
        QVERIFY(receiver.errors.isEmpty());
    }

    void tcpLinkFailsWhenTheServerGoes()
    {
        auto server = std::make_unique<SimulatorServer>(Protocol::Hsp5, options());
        QVERIFY(server->listenTcp(QStringLiteral("127.0.0.1"), 0, nullptr));
        ConnectionSettings settings;
        const QString target = QStringLiteral("tcp:127.0.0.1:%1").arg(server->tcpPort());
        QVERIFY(settings.parseTarget(target, nullptr));
        TcpLink link(settings);
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        QTRY_VERIFY(server->hasClient());
        server.reset();
        QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, 2000);
        QVERIFY2(failed.at(0).at(0).toString().contains(QStringLiteral("closed")),
                 qPrintable(failed.at(0).at(0).toString()));
        QVERIFY(!link.isOpen());
    }

    void serialLinkExchangesTelegramsOverThePty()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("drive"));
        SimulatorServer server(Protocol::Din66019II, options());
        QString error;
        QVERIFY2(server.listenPty(path, &error), qPrintable(error));
        ConnectionSettings settings;
        settings.protocol = Protocol::Din66019II;
        QVERIFY(settings.parseTarget(QStringLiteral("serial:") + path, nullptr));
        SerialLink link(settings);
        Receiver receiver(link, Protocol::Din66019II);
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        // As seed 003 5.48, at drive 1: EOT 0 1, read 0200h set mask 01, invoke id 1.
        Telegram request = Telegram::request(Service::ParameterValue, Access::Read,
                                             ParameterValue{0x0200, 0x01, 0});
        request.operatorInvoke = 1;
        request.driveAddress = 1;
        link.send(receiver.codec->encode(request));
        QTRY_COMPARE(receiver.telegrams.size(), 1);
        QCOMPARE(receiver.telegrams[0].operatorInvoke, quint8(1));
        QCOMPARE(receiver.telegrams[0].ack, Ack::Ok);
        QCOMPARE(receiver.raw.at(0), '\x02'); // STX: a good read answer

        // Close and open again: the pseudo-terminal serves the next session too.
        link.close();
        link.open();
        QTRY_COMPARE(opened.count(), 2);
        request.operatorInvoke = 2;
        link.send(receiver.codec->encode(request));
        QTRY_COMPARE(receiver.telegrams.size(), 2);
        QCOMPARE(receiver.telegrams[1].operatorInvoke, quint8(2));
        QCOMPARE(failed.count(), 0);
    }

    void serialLinkFailsWhenThePtyGoes()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("drive"));
        auto server = std::make_unique<SimulatorServer>(Protocol::Hsp5, options());
        QVERIFY(server->listenPty(path, nullptr));
        ConnectionSettings settings;
        QVERIFY(settings.parseTarget(QStringLiteral("serial:") + path, nullptr));
        SerialLink link(settings);
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        server.reset();
        QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, 2000);
        const QString reason = failed.at(0).at(0).toString();
        QVERIFY2(reason.contains(path), qPrintable(reason));
        QVERIFY(!link.isOpen());
    }
};

QTEST_GUILESS_MAIN(TestLinkToSimulator)
#include "tst_linktosimulator.moc"
