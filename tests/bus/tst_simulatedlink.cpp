#include "BusTestSupport.h"
#include "bus/LinkFactory.h"
#include "bus/SimulatedBus.h"
#include "bus/SimulatedLink.h"
#include "link/SerialLink.h"
#include "link/TcpLink.h"
#include "Translations.h"

#include <QSignalSpy>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::BusTest;

namespace {

ConnectionSettings simulated(Protocol protocol, QList<int> addresses = {1})
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.protocol = protocol;
    settings.simulation.driveAddresses = addresses;
    settings.simulation.replyLatencyUs = 200;
    return settings;
}

} // namespace

// The in-process link to simulated drives, and makeLink() choosing the link for the settings.
class TestSimulatedLink : public QObject
{
    Q_OBJECT
private slots:
    // English as the programs show it: with its catalogue, which holds the plural forms.
    void initTestCase() { QVERIFY(installTranslations(QStringLiteral("en"))); }

    void opensFromTheEventLoop()
    {
        SimulatedLink link(simulated(Protocol::Hsp5));
        QSignalSpy opened(&link, &Link::opened);
        link.open();
        QCOMPARE(opened.count(), 0); // not from within open()
        QTRY_COMPARE(opened.count(), 1);
        QVERIFY(link.isOpen());
        QCOMPARE(link.description(), QStringLiteral("simulated drive"));
    }

    void answersHsp5Requests()
    {
        SimulatedLink link(simulated(Protocol::Hsp5));
        QSignalSpy opened(&link, &Link::opened);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        Operator op(Protocol::Hsp5);
        QList<Telegram> replies;
        connect(&link, &Link::received, this,
                [&](const QByteArray &bytes) { replies += op.telegrams(bytes); });
        link.send(op.encode(readValue(kStateAddress, 1)));
        link.send(op.encode(readValue(kStateAddress, 2)));
        QTRY_COMPARE(replies.size(), 2);
        QCOMPARE(replies[0].operatorInvoke, quint8(1));
        QCOMPARE(replies[1].operatorInvoke, quint8(2));
        QCOMPARE(link.bus().counters().replies, 2);
    }

    void pacedDinDrivesAnswerInTurn()
    {
        ConnectionSettings settings = simulated(Protocol::Din66019II, {1, 2});
        settings.simulation.paced = true;
        settings.simulation.baudRate = 115200;
        SimulatedLink link(settings);
        QCOMPARE(link.description(), QStringLiteral("simulated drives 1, 2"));
        QSignalSpy opened(&link, &Link::opened);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        Operator op(Protocol::Din66019II);
        QList<Telegram> replies;
        connect(&link, &Link::received, this,
                [&](const QByteArray &bytes) { replies += op.telegrams(bytes); });
        link.send(op.encode(readValue(kStateAddress, 1, 1)));
        QTRY_COMPARE(replies.size(), 1);
        link.send(op.encode(readValue(kStateAddress, 2, 2)));
        QTRY_COMPARE(replies.size(), 2);
        QCOMPARE(replies[1].operatorInvoke, quint8(2));
    }

    void closedLinkDeliversNothing()
    {
        ConnectionSettings settings = simulated(Protocol::Hsp5);
        settings.simulation.replyLatencyUs = 20'000;
        SimulatedLink link(settings);
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy received(&link, &Link::received);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        Operator op(Protocol::Hsp5);
        QList<Telegram> replies;
        connect(&link, &Link::received, this,
                [&](const QByteArray &bytes) { replies += op.telegrams(bytes); });
        link.send(op.encode(readValue(kStateAddress, 1)));
        link.close();
        QVERIFY(!link.isOpen());
        // Opened again, the link answers a request sent then, and nothing else: the answer to
        // the first one, due earlier, never comes.
        link.open();
        QTRY_COMPARE(opened.count(), 2);
        link.send(op.encode(readValue(kStateAddress, 2)));
        QTRY_VERIFY(!replies.isEmpty());
        QCOMPARE(replies.constFirst().operatorInvoke, quint8(2));
        QCOMPARE(replies.size(), 1);
    }

    void closeBeforeOpenedCancelsOpening()
    {
        SimulatedLink link(simulated(Protocol::Hsp5));
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy received(&link, &Link::received);
        link.open();
        link.close();
        // Opened again, the link answers a request: by then the first opening would have
        // completed, had it not been cancelled.
        link.open();
        QTRY_VERIFY(link.isOpen());
        Operator op(Protocol::Hsp5);
        link.send(op.encode(readValue(kStateAddress, 1)));
        QTRY_VERIFY(!received.isEmpty());
        QCOMPARE(opened.count(), 1);
    }

    void makeLinkFollowsTheSettings()
    {
        ConnectionSettings settings = simulated(Protocol::Hsp5);
        std::unique_ptr<Link> link = makeLink(settings);
        QVERIFY(qobject_cast<SimulatedLink *>(link.get()));
        QVERIFY(settings.parseTarget(QStringLiteral("tcp:127.0.0.1:4001"), nullptr));
        link = makeLink(settings);
        QVERIFY(qobject_cast<TcpLink *>(link.get()));
        QVERIFY(settings.parseTarget(QStringLiteral("serial:/dev/ttyUSB0"), nullptr));
        QObject parent;
        link = makeLink(settings, &parent);
        QVERIFY(qobject_cast<SerialLink *>(link.get()));
        QCOMPARE(link->parent(), &parent);
        link.reset();
    }
};

QTEST_GUILESS_MAIN(TestSimulatedLink)
#include "tst_simulatedlink.moc"
