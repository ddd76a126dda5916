#include "ClientTestSupport.h"

#include "bus/FaultInjector.h"
#include "bus/SimulatedBus.h"

#include "sim/DatabaseLoader.h"
#include "sim/ParameterDatabase.h"

#include <QDir>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <algorithm>
#include <bit>
#include <map>
#include <set>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

Q_DECLARE_METATYPE(DriveDesk::Protocol)

namespace {

// The scan against a line without parity that flips one bit in a byte now and then, in both
// directions: only the protocol's checksum stands between the flip and the decoder, and it
// lets some through (docs/client.md). Whatever the seed, a scan either equals the clean scan or
// says what it could not settle: never a wrong name, limit or value, never a parameter left
// out without a word.

ClientOptions quickTimeouts()
{
    ClientOptions options;
    options.timeoutMs = 15; // in process without latency: keep the lost answers cheap
    return options;
}

DriveDescription scanned(Protocol protocol, SimulationOptions simulation, ScanOptions options = {})
{
    Session s(simulated(protocol, simulation), quickTimeouts());
    if (!s.connected())
        return {};
    QFuture<DriveDescription> scan = s.client->scan(options);
    if (!waitFinished(scan, 120000) || scan.resultCount() == 0)
        return {};
    return scan.result();
}

QString hex(quint16 address)
{
    return QStringLiteral("%1h").arg(address, 4, 16, QLatin1Char('0'));
}

// The metadata fields in which `a` differs from `b`.
QStringList differingMetadata(const ParameterDescription &a, const ParameterDescription &b)
{
    QStringList fields;
    if (a.minimum != b.minimum || a.maximum != b.maximum)
        fields << QStringLiteral("limits %1..%2").arg(a.minimum).arg(a.maximum);
    if (a.defaultValue != b.defaultValue)
        fields << QStringLiteral("default %1").arg(a.defaultValue);
    if (a.properties1 != b.properties1 || a.properties2 != b.properties2)
        fields << QStringLiteral("properties");
    if (a.scaling != b.scaling)
        fields << QStringLiteral("scaling");
    if (a.plaintextIndices != b.plaintextIndices)
        fields << QStringLiteral("plaintext indices");
    if (a.plaintexts != b.plaintexts) {
        fields << QStringLiteral("plaintexts (%1 definitions, %2 expected)")
                      .arg(a.plaintexts.size())
                      .arg(b.plaintexts.size());
    }
    return fields;
}

// What `noisy` holds that the clean scan does not, and what it leaves out without a word.
// `live`: parameters whose values change on their own.
QStringList silentlyWrong(const DriveDescription &clean, const DriveDescription &noisy,
                          const std::set<quint16> &live)
{
    QStringList wrong;
    const bool incomplete = !noisy.incompleteReason.isEmpty();
    for (const GroupDescription &group : noisy.groups) {
        const GroupDescription *expected = clean.findGroup(group.id);
        if (!expected) {
            wrong << QStringLiteral("group %1 that the drive does not have").arg(group.id);
            continue;
        }
        if (group.name != expected->name && !(group.name.isEmpty() && incomplete))
            wrong << QStringLiteral("group %1 named '%2'").arg(group.id, group.name);
        if (group.index != expected->index || group.parameterCount != expected->parameterCount
            || group.highestNumber != expected->highestNumber)
            wrong << QStringLiteral("group %1: properties").arg(group.id);
    }
    for (const GroupDescription &group : clean.groups) {
        if (!noisy.findGroup(group.id) && !incomplete)
            wrong << QStringLiteral("group %1 left out").arg(group.id);
    }
    for (const GroupDescription &group : clean.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (!noisy.find(parameter.address) && !incomplete)
                wrong << QStringLiteral("%1 left out").arg(hex(parameter.address));
        }
    }
    for (const GroupDescription &group : noisy.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            const QString id = hex(parameter.address);
            const ParameterDescription *expected = clean.find(parameter.address);
            if (!expected) {
                wrong << QStringLiteral("%1 that the drive does not have").arg(id);
                continue;
            }
            const bool marked = !parameter.error.isEmpty();
            // A scan that calls itself complete holds only what the drive itself said: an error
            // the clean line does not give (its refusals do) is a parameter left unread.
            // A live value may come out unconfirmed (no two reads agree while it moves), then
            // without a value: no setting, so no reason to call the scan incomplete. The clean
            // scan is no exception: a client thread held up past a timeout makes a clean line
            // show errors too, and its live values are then no measure of the other's.
            const auto unread = [](const ParameterDescription &p) {
                return std::all_of(p.values.begin(), p.values.end(),
                                   [](const std::optional<qint32> &v) { return !v; });
            };
            const bool unconfirmedLive
                = live.count(parameter.address) && (unread(parameter) || unread(*expected));
            if (!incomplete && parameter.error != expected->error && !unconfirmedLive)
                wrong << QStringLiteral("%1 not read (%2) in a scan called complete")
                             .arg(id, parameter.error);
            if (parameter.name != expected->name && !(parameter.name.isEmpty() && marked))
                wrong << QStringLiteral("%1 named '%2'").arg(id, parameter.name);
            if (!marked) {
                const QStringList fields = differingMetadata(parameter, *expected);
                if (!fields.isEmpty())
                    wrong << QStringLiteral("%1: %2").arg(id, fields.join(QStringLiteral(", ")));
            }
            if (live.count(parameter.address))
                continue;
            for (std::size_t set = 0; set < parameter.values.size(); ++set) {
                const std::optional<qint32> &value = parameter.values[set];
                if (value ? value != expected->values[set] : (expected->values[set] && !marked))
                    wrong << QStringLiteral("%1 set %2: %3")
                                 .arg(id)
                                 .arg(set)
                                 .arg(value ? QString::number(*value) : QStringLiteral("missing"));
            }
        }
    }
    return wrong;
}

// The simulated line behind a client whose thread is held up at every `every`-th telegram, from
// the first on, between the moment the request's timeout starts and the moment its bytes go out,
// as a loaded machine holds a thread up: the answer comes after its timeout although no byte on
// the line was touched.
class StallingLink : public Link
{
public:
    StallingLink(const ConnectionSettings &settings, int every, int stallMs)
        : m_line(makeLink(settings))
        , m_every(every)
        , m_stallMs(stallMs)
    {
        connect(m_line.get(), &Link::opened, this, [this] { reportOpened(); });
        connect(m_line.get(), &Link::received, this,
                [this](const QByteArray &bytes) { handOn(bytes); });
        connect(m_line.get(), &Link::lineError, this,
                [this](const QString &reason) { handOnLineError(reason); });
        connect(m_line.get(), &Link::failed, this, [this](const QString &reason) { fail(reason); });
    }

    QString description() const override { return m_line->description(); }

protected:
    void openTransport() override { m_line->open(); }
    void closeTransport() override { m_line->close(); }
    void transmit(const QByteArray &bytes) override
    {
        if (m_sent++ % m_every == 0)
            QThread::msleep(m_stallMs); // the client's thread, not the line
        m_line->send(bytes);
    }

private:
    std::unique_ptr<Link> m_line;
    const int m_every;
    const int m_stallMs;
    int m_sent = 0;
};

// The simulated drive's live signals: their values change on their own.
std::set<quint16> liveParameters()
{
    std::set<quint16> live;
    for (const Sim::SimParameter &parameter : Sim::standardDatabase()->parameters()) {
        if (parameter.signal != Sim::LiveSignal::None)
            live.insert(parameter.address);
    }
    return live;
}

} // namespace

class TestClientNoise : public QObject
{
    Q_OBJECT
private slots:
    void flippedBytesArriveUnflaggedAndReproducibly()
    {
        SimulationOptions options;
        options.flipByteRate = 0.05;
        options.seed = 11;
        const QByteArray sent(10000, '\x55');
        BusCounters counters;
        FaultInjector faults(options, 8, &counters);
        QList<qsizetype> flagged;
        const QByteArray received = faults.pass(sent, &flagged);
        QVERIFY(flagged.isEmpty()); // no parity: the receiver is told nothing
        QCOMPARE(received.size(), sent.size());
        int changed = 0;
        for (qsizetype i = 0; i < sent.size(); ++i) {
            const auto difference = quint8(sent[i] ^ received[i]);
            if (difference == 0)
                continue;
            ++changed;
            QVERIFY(std::has_single_bit(unsigned(difference)));
        }
        QCOMPARE(changed, counters.flippedBytes);
        QVERIFY2(changed > 400 && changed < 600, qPrintable(QString::number(changed)));
        // The same seed flips the same bits.
        BusCounters again;
        FaultInjector same(options, 8, &again);
        QCOMPARE(same.pass(sent, nullptr), received);
    }

    void aScanOnANoisyLineIsRightOrSaysWhatItMissed_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<double>("rate");
        QTest::addColumn<quint32>("seeds");
        // At 5 % most telegrams need several attempts: fewer seeds keep the test quick.
        QTest::newRow("hsp5 1%") << Protocol::Hsp5 << 0.01 << 20u;
        QTest::newRow("hsp5 5%") << Protocol::Hsp5 << 0.05 << 4u;
        QTest::newRow("din66019ii 1%") << Protocol::Din66019II << 0.01 << 20u;
        QTest::newRow("din66019ii 5%") << Protocol::Din66019II << 0.05 << 4u;
    }
    void aScanOnANoisyLineIsRightOrSaysWhatItMissed()
    {
        QFETCH(Protocol, protocol);
        QFETCH(double, rate);
        QFETCH(quint32, seeds);
        // ru (live values, shared plaintexts) and op (values per set): enough of the drive
        // for many seeds to stay quick.
        ScanOptions groups;
        groups.groupPages = { 0x02, 0x03 };
        const DriveDescription clean = scanned(protocol, fast(), groups);
        QVERIFY2(clean.incompleteReason.isEmpty(), qPrintable(clean.incompleteReason));
        QCOMPARE(clean.groups.size(), 2);
        const std::set<quint16> live = liveParameters();

        int equal = 0;
        int incomplete = 0;
        QElapsedTimer timer;
        timer.start();
        // To look into one seed: DRIVEDESK_NOISE_SEED (the first seed), DRIVEDESK_NOISE_VERBOSE.
        const quint32 first = qEnvironmentVariableIntValue("DRIVEDESK_NOISE_SEED");
        for (quint32 seed = std::max(first, 1u); seed <= seeds; ++seed) {
            SimulationOptions simulation = fast();
            simulation.flipByteRate = rate;
            simulation.seed = seed;
            const DriveDescription noisy = scanned(protocol, simulation, groups);
            QVERIFY2(!noisy.groups.isEmpty(), qPrintable(noisy.incompleteReason));
            const QStringList wrong = silentlyWrong(clean, noisy, live);
            QVERIFY2(wrong.isEmpty(),
                     qPrintable(QStringLiteral("seed %1: %2 (%3)")
                                    .arg(seed)
                                    .arg(wrong.join(QStringLiteral("; ")))
                                    .arg(noisy.incompleteReason)));
            if (qEnvironmentVariableIsSet("DRIVEDESK_NOISE_VERBOSE"))
                qInfo("seed %u: %s", seed, qPrintable(noisy.incompleteReason));
            if (noisy.incompleteReason.isEmpty())
                ++equal;
            else
                ++incomplete;
        }
        qInfo("%d of %d scans complete and right, %d say what they could not settle; %lld ms",
              equal, seeds, incomplete, timer.elapsed());
    }

    void aCleanScanOnASlowThreadStaysTheReference_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }
    void aCleanScanOnASlowThreadStaysTheReference()
    {
        // A clean line, but a client thread held up for longer than a timeout: the line shows
        // errors, and from then on the scan confirms every answer. A live value then comes out
        // unconfirmed (without a value, its error says why) in the very scan the others are
        // compared with, while a scan on a quiet thread reads it at once. Neither is wrong.
        QFETCH(Protocol, protocol);
        QTemporaryDir cache;
        QVERIFY(cache.isValid());
        ScanOptions refresh;
        refresh.metadata = MetadataSource::RefreshCache;
        refresh.cacheDirectory = cache.path();
        scanned(protocol, fast(), refresh);
        QVERIFY(!QDir(cache.path()).entryList(QDir::Files).isEmpty());

        // Sy holds the scope timer (a live value that moves every millisecond), Ec the encoder
        // position (the live value of the failure on a loaded machine that led to this test).
        ScanOptions groups;
        groups.groupPages = { 0x00, 0x10 };
        ScanOptions cached = groups;
        cached.metadata = MetadataSource::Cache;
        cached.cacheDirectory = cache.path();
        const DriveDescription warm = scanned(protocol, fast(), cached);
        QVERIFY2(warm.incompleteReason.isEmpty(), qPrintable(warm.incompleteReason));
        QVERIFY(warm.metadataFromCache);

        // The answer takes a moment, as every drive's does: with none, the simulated drive's
        // answer, due on this same thread the moment the bytes go out, would still be taken
        // before the timeout, however long the thread was held up.
        SimulationOptions simulation = fast();
        simulation.replyLatencyUs = 1000;
        const LinkMaker stalling = [](const ConnectionSettings &settings) -> std::unique_ptr<Link> {
            return std::make_unique<StallingLink>(settings, 40, 25);
        };
        DriveClient client(simulated(protocol, simulation), stalling, quickTimeouts());
        QSignalSpy traffic(&client, &DriveClient::traffic);
        client.connectToDrive();
        QVERIFY(QTest::qWaitFor(
            [&client] { return client.state() == DriveClient::State::Connected; }, kWaitMs));
        QFuture<DriveDescription> scan = client.scan(groups);
        QVERIFY(waitFinished(scan, 120000));
        QCOMPARE(scan.resultCount(), 1);
        const DriveDescription reference = scan.result();
        QVERIFY(std::any_of(traffic.cbegin(), traffic.cend(), [](const QList<QVariant> &record) {
            return record.at(0).value<TrafficRecord>().kind == TrafficRecord::Kind::Error;
        }));
        const std::set<quint16> live = liveParameters();
        QStringList unconfirmed;
        for (const GroupDescription &group : reference.groups) {
            for (const ParameterDescription &parameter : group.parameters) {
                if (live.count(parameter.address) && !parameter.values[0])
                    unconfirmed << hex(parameter.address);
            }
        }
        QVERIFY2(!unconfirmed.isEmpty(), "no live value came out unconfirmed: nothing was tried");

        const QStringList wrong = silentlyWrong(reference, warm, live);
        QVERIFY2(wrong.isEmpty(),
                 qPrintable(QStringLiteral("%1 (unconfirmed in the reference: %2)")
                                .arg(wrong.join(QStringLiteral("; ")),
                                     unconfirmed.join(QStringLiteral(", ")))));
        QCOMPARE(warm.parameterCount(), reference.parameterCount());
    }

    void theCacheAfterNoisyScansHoldsWhatACleanScanReads_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }
    void theCacheAfterNoisyScansHoldsWhatACleanScanReads()
    {
        QFETCH(Protocol, protocol);
        QTemporaryDir cache;
        QVERIFY(cache.isValid());
        ScanOptions refresh;
        refresh.metadata = MetadataSource::RefreshCache;
        refresh.cacheDirectory = cache.path();
        // Noisy scans until one of them is complete: only such a one writes the cache. The
        // line shows errors within the first telegrams, so every answer kept is confirmed.
        bool stored = false;
        for (quint32 seed = 1; seed <= 8 && !stored; ++seed) {
            SimulationOptions simulation = fast();
            simulation.flipByteRate = 0.003;
            simulation.seed = seed;
            scanned(protocol, simulation, refresh);
            stored = !QDir(cache.path()).entryList(QDir::Files).isEmpty();
        }
        QVERIFY(stored);
        const DriveDescription cold = scanned(protocol, fast());
        const std::set<quint16> live = liveParameters();

        ScanOptions cached;
        cached.metadata = MetadataSource::Cache;
        cached.cacheDirectory = cache.path();
        const DriveDescription warm = scanned(protocol, fast(), cached);
        QVERIFY2(warm.incompleteReason.isEmpty(), qPrintable(warm.incompleteReason));
        QVERIFY(warm.metadataFromCache);
        const QStringList wrong = silentlyWrong(cold, warm, live);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(QStringLiteral("; "))));
        QCOMPARE(warm.parameterCount(), cold.parameterCount());
    }
};

QTEST_GUILESS_MAIN(TestClientNoise)
#include "tst_clientnoise.moc"
