#include "ClientTestSupport.h"

#include "parameters/MetadataCache.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

namespace {

struct Scanned {
    DriveDescription drive;
    QList<Service> services; // of every request the scan sent
};

Scanned scan(const ConnectionSettings &settings, MetadataSource metadata, const QString &cache,
             const std::function<void(Session &)> &before = {})
{
    Session s(settings);
    if (!s.connected())
        return {};
    if (before)
        before(s);
    s.traffic->clear();
    ScanOptions options;
    options.metadata = metadata;
    options.cacheDirectory = cache;
    QFuture<DriveDescription> future = s.client->scan(options);
    if (!waitFinished(future, 120000))
        return {};
    Scanned result{future.result(), {}};
    result.services = sentServices(s.records(), *makeCodec(settings.protocol));
    return result;
}

// The groups without their values: live values change from one read to the next.
QList<GroupDescription> metadataOf(DriveDescription drive)
{
    for (GroupDescription &group : drive.groups) {
        for (ParameterDescription &parameter : group.parameters) {
            parameter.values = {};
            parameter.error.clear();
        }
    }
    return drive.groups;
}

int metadataRequests(const QList<Service> &services)
{
    return int(std::count_if(services.cbegin(), services.cend(), [](Service service) {
        // Service 13 (over DIN66019II) is the identification, asked on every connection.
        return service != Service::ParameterValue && service != Service::ParameterValueStandard
               && service != Service::Fieldbus;
    }));
}

QStringList cacheFiles(const QString &cache)
{
    return QDir(cache).entryList(QDir::Files);
}

} // namespace

Q_DECLARE_METATYPE(DriveDesk::Protocol)

// The scan and the metadata cache against the simulated drive: a drive of a cached kind has only
// its identification and values read; anything else is read cold.
class TestClientCache : public QObject
{
    Q_OBJECT
private slots:
    void aReconnectReadsOnlyIdentificationAndValues_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }
    void aReconnectReadsOnlyIdentificationAndValues()
    {
        QFETCH(Protocol, protocol);
        QTemporaryDir cache;
        const ConnectionSettings settings = simulated(protocol, fast());
        const Scanned cold = scan(settings, MetadataSource::Cache, cache.path());
        QVERIFY2(cold.drive.incompleteReason.isEmpty(), qPrintable(cold.drive.incompleteReason));
        QVERIFY(!cold.drive.metadataFromCache);
        QCOMPARE(cacheFiles(cache.path()).size(), 1);

        // Another connection to the same kind of drive, with a value changed meanwhile.
        const Scanned warm = scan(settings, MetadataSource::Cache, cache.path(), [](Session &s) {
            QVERIFY(s.call(s.client->writeValue(kMaxSpeedForward, 2222, 0x08)).ok());
        });
        QVERIFY2(warm.drive.incompleteReason.isEmpty(), qPrintable(warm.drive.incompleteReason));
        QVERIFY(warm.drive.metadataFromCache);
        QCOMPARE(metadataOf(warm.drive), metadataOf(cold.drive));
        QCOMPARE(warm.drive.parameterCount(), cold.drive.parameterCount());
        QCOMPARE(warm.drive.find(kMaxSpeedForward)->values[3], std::optional<qint32>(2222));
        QCOMPARE(warm.drive.find(kMaxSpeedForward)->values[2], std::optional<qint32>(3000));
        QCOMPARE(warm.drive.find(kRatedCurrent)->values[0], std::optional<qint32>(105));
        // Nothing but values: no group, name, limit or text request at all.
        QCOMPARE(metadataRequests(warm.services), 0);
        QVERIFY2(warm.services.size() * 5 < cold.services.size(),
                 qPrintable(QStringLiteral("%1 requests, cold %2")
                                .arg(warm.services.size())
                                .arg(cold.services.size())));
    }

    // The progress of a scan of a cached kind names the identification it reads as every other
    // text does: in words, the address with a lower-case h.
    void theIdentificationReadIsNamedInWords()
    {
        QTemporaryDir cache;
        const ConnectionSettings settings = simulated(Protocol::Hsp5, fast());
        QVERIFY(scan(settings, MetadataSource::Cache, cache.path()).drive.incompleteReason.isEmpty());

        Session s(settings);
        QVERIFY(s.connected());
        ScanOptions options;
        options.metadata = MetadataSource::Cache;
        options.cacheDirectory = cache.path();
        QFuture<DriveDescription> future = s.client->scan(options);
        QStringList texts;
        QFutureWatcher<DriveDescription> watcher;
        connect(&watcher, &QFutureWatcherBase::progressTextChanged, this,
                [&texts](const QString &text) { texts << text; });
        watcher.setFuture(future);
        QVERIFY(waitFinished(future, 120000));
        QTRY_VERIFY(watcher.isFinished());
        const QStringList identification = texts.filter(QStringLiteral("dentification"),
                                                        Qt::CaseInsensitive);
        QVERIFY2(!identification.isEmpty(), qPrintable(texts.join(QLatin1Char('\n'))));
        for (const QString &text : identification) {
            QVERIFY2(QRegularExpression(QStringLiteral("^identification [0-9A-F]{4}h$"))
                         .match(text)
                         .hasMatch(),
                     qPrintable(text));
        }
    }

    void anotherKindIsReadColdAndCachedBeside()
    {
        QTemporaryDir cache;
        QVERIFY(scan(simulated(Protocol::Hsp5, fast()), MetadataSource::Cache, cache.path())
                    .drive.incompleteReason.isEmpty());

        // A drive with more parameters runs other software (In.06): never the first's metadata.
        SimulationOptions bigger = fast();
        bigger.parameterCount = 300;
        const Scanned other = scan(simulated(Protocol::Hsp5, bigger), MetadataSource::Cache,
                                   cache.path());
        QVERIFY(!other.drive.metadataFromCache);
        QCOMPARE(other.drive.parameterCount(), 300);
        QVERIFY(metadataRequests(other.services) > 0);
        QCOMPARE(cacheFiles(cache.path()).size(), 2);

        const Scanned again = scan(simulated(Protocol::Hsp5, bigger), MetadataSource::Cache,
                                   cache.path());
        QVERIFY(again.drive.metadataFromCache);
        QCOMPARE(again.drive.parameterCount(), 300);
        const Scanned standard = scan(simulated(Protocol::Hsp5, fast()), MetadataSource::Cache,
                                      cache.path());
        QVERIFY(standard.drive.metadataFromCache);
        QCOMPARE(standard.drive.parameterCount(), 206);
    }

    void eachLanguageIsItsOwnEntry()
    {
        QTemporaryDir cache;
        ConnectionSettings german = simulated(Protocol::Hsp5, fast());
        german.language = Language::German;
        QVERIFY(scan(simulated(Protocol::Hsp5, fast()), MetadataSource::Cache, cache.path())
                    .drive.incompleteReason.isEmpty());
        const Scanned cold = scan(german, MetadataSource::Cache, cache.path());
        QVERIFY(!cold.drive.metadataFromCache);
        QCOMPARE(cold.drive.find(kMaxSpeedForward)->name, QStringLiteral("Max. Drehzahl rechts"));
        const Scanned warm = scan(german, MetadataSource::Cache, cache.path());
        QVERIFY(warm.drive.metadataFromCache);
        QCOMPARE(warm.drive.find(kMaxSpeedForward)->name, QStringLiteral("Max. Drehzahl rechts"));
        QCOMPARE(cacheFiles(cache.path()).size(), 1);
    }

    void onlyACompleteScanIsKept()
    {
        QTemporaryDir cache;
        const ConnectionSettings settings = simulated(Protocol::Hsp5, fast());
        Session s(settings);
        QVERIFY(s.connected());
        ScanOptions someGroups;
        someGroups.groupPages = {0x00, 0x03, 0x0E};
        someGroups.metadata = MetadataSource::Cache;
        someGroups.cacheDirectory = cache.path();
        QFuture<DriveDescription> partial = s.client->scan(someGroups);
        QVERIFY(waitFinished(partial, 60000));
        QVERIFY(partial.result().incompleteReason.isEmpty());
        QVERIFY(cacheFiles(cache.path()).isEmpty());

        // Reading from the drive alone neither reads nor writes the cache.
        const Scanned fromTheDrive = scan(settings, MetadataSource::Drive, cache.path());
        QVERIFY(fromTheDrive.drive.incompleteReason.isEmpty());
        QVERIFY(cacheFiles(cache.path()).isEmpty());

        // A cancelled scan is not kept either.
        ConnectionSettings slow = settings;
        slow.simulation.replyLatencyUs = 2000; // slow enough to cancel halfway
        Session slowly(slow);
        QVERIFY(slowly.connected());
        ScanOptions everything;
        everything.metadata = MetadataSource::Cache;
        everything.cacheDirectory = cache.path();
        QFuture<DriveDescription> cancelled = slowly.client->scan(everything);
        QTRY_VERIFY(cancelled.progressValue() > 0);
        cancelled.cancel();
        QVERIFY(waitFinished(cancelled));
        QVERIFY(cacheFiles(cache.path()).isEmpty());
    }

    void readingAgainIgnoresTheCacheAndRefreshesIt()
    {
        QTemporaryDir cache;
        const ConnectionSettings settings = simulated(Protocol::Hsp5, fast());
        const Scanned cold = scan(settings, MetadataSource::Cache, cache.path());
        QVERIFY(cold.drive.incompleteReason.isEmpty());
        const QString file = QDir(cache.path()).filePath(cacheFiles(cache.path()).constFirst());
        const QDateTime written = QFileInfo(file).lastModified();
        QTest::qWait(20);
        const Scanned again = scan(settings, MetadataSource::RefreshCache, cache.path());
        QVERIFY(!again.drive.metadataFromCache);
        QVERIFY(metadataRequests(again.services) > 0);
        QVERIFY(QFileInfo(file).lastModified() > written);
    }

    void aCorruptCacheFileIsReportedAndReplaced()
    {
        QTemporaryDir cache;
        const ConnectionSettings settings = simulated(Protocol::Hsp5, fast());
        const Scanned cold = scan(settings, MetadataSource::Cache, cache.path());
        QVERIFY(cold.drive.incompleteReason.isEmpty());
        const QString file = QDir(cache.path()).filePath(cacheFiles(cache.path()).constFirst());
        QFile broken(file);
        QVERIFY(broken.open(QIODevice::WriteOnly | QIODevice::Truncate));
        broken.write("{\"format\": \"drivedesk-metadata-cache\", \"version\": 1, \"kind\": [");
        broken.close();

        const Scanned repaired = scan(settings, MetadataSource::Cache, cache.path());
        QVERIFY(!repaired.drive.metadataFromCache);
        QCOMPARE(repaired.drive.warnings.size(), 1);
        QVERIFY2(repaired.drive.warnings.constFirst().contains(file),
                 qPrintable(repaired.drive.warnings.constFirst()));
        QCOMPARE(metadataOf(repaired.drive), metadataOf(cold.drive));

        const Scanned warm = scan(settings, MetadataSource::Cache, cache.path());
        QVERIFY(warm.drive.metadataFromCache);
        QVERIFY(warm.drive.warnings.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestClientCache)
#include "tst_clientcache.moc"
