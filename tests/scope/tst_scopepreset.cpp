#include "scope/ScopePreset.h"
#include "scope/ScopePresetLibrary.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace DriveDesk;

namespace {

ScopePreset examplePreset()
{
    ScopePreset preset;
    preset.name = QStringLiteral("Speed step");
    preset.driveKind = QStringLiteral("In.00=1234, In.06=180");
    preset.channels[0].source = ScopeSourceText{QStringLiteral("ru.03"), 0};
    preset.channels[0].color = QStringLiteral("#112233");
    preset.channels[1].source = ScopeSourceText{QStringLiteral("op.11"), 2};
    preset.channels[1].ownAxis = true;
    preset.channels[2].source = ScopeSourceText{}; // off
    preset.channels[2].visible = false;
    // channel 4: as the drive has it
    preset.trigger.channel = 1;
    preset.trigger.level = 12.5;
    preset.trigger.edge = ScopeTriggerSettings::Edge::Falling;
    preset.trigger.preTriggerShare = 0.35;
    preset.trigger.windowMs = 2500;
    preset.rollSeconds = 4.5;
    preset.rateLimitHz = 250;
    return preset;
}

QJsonObject exampleJson()
{
    return QJsonDocument::fromJson(ScopePresetFile::toJson(examplePreset())).object();
}

QByteArray withChannelField(int channel, const QString &key, const QJsonValue &value)
{
    QJsonObject root = exampleJson();
    QJsonArray channels = root.value(QStringLiteral("channels")).toArray();
    QJsonObject object = channels.at(channel).toObject();
    object.insert(key, value);
    channels.replace(channel, object);
    root.insert(QStringLiteral("channels"), channels);
    return QJsonDocument(root).toJson();
}

QByteArray withField(const QString &key, const QJsonValue &value)
{
    QJsonObject root = exampleJson();
    root.insert(key, value);
    return QJsonDocument(root).toJson();
}

QByteArray withTriggerField(const QString &key, const QJsonValue &value)
{
    QJsonObject root = exampleJson();
    QJsonObject trigger = root.value(QStringLiteral("trigger")).toObject();
    trigger.insert(key, value);
    root.insert(QStringLiteral("trigger"), trigger);
    return QJsonDocument(root).toJson();
}

bool write(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

} // namespace

// A scope preset saved and loaded again is the same set-up; every kind of bad file is refused
// with the file and what is wrong in it; the library lists the presets beside a plant first.
class TestScopePreset : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void aPresetSavedLoadsAsTheSameSetUp()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("step.json"));
        QString error;
        QVERIFY2(ScopePresetFile::save(path, examplePreset(), &error), qPrintable(error));
        const std::optional<ScopePreset> loaded = ScopePresetFile::load(path, &error);
        QVERIFY2(loaded, qPrintable(error));
        QVERIFY(*loaded == examplePreset());
        QCOMPARE(loaded->channels[1].source->text(), QStringLiteral("op.11@2"));
        QVERIFY(loaded->channels[2].source && loaded->channels[2].source->isOff());
        QVERIFY(!loaded->channels[3].source);
        QCOMPARE(loaded->trigger.level, 12.5);

        // What a user reads in the file: the sources as written, channels counted from 1.
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.contains("\"op.11@2\""));
        QVERIFY(text.contains("\"off\""));
        QVERIFY(text.contains("\"channel\": 2"));
        QVERIFY(text.contains("\"format\": \"drivedesk-scope-preset\""));
    }

    void aBadFileIsRefusedSayingWhatIsWrong_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        QTest::newRow("not JSON") << QByteArray("{\"format\": ") << QStringLiteral("not JSON");
        QTest::newRow("not an object") << QByteArray("[1, 2]")
                                       << QStringLiteral("not a DriveDesk scope preset");
        QTest::newRow("another format")
            << withField(QStringLiteral("format"), QStringLiteral("drivedesk-plant"))
            << QStringLiteral("not a DriveDesk scope preset");
        QTest::newRow("newer version") << withField(QStringLiteral("version"), 2)
                                       << QStringLiteral("version: 2 is a newer format");
        QTest::newRow("source not a parameter")
            << withChannelField(2, QStringLiteral("source"), QStringLiteral("speed"))
            << QStringLiteral("channel 3's source: 'speed' is not a parameter id");
        QTest::newRow("source's set out of range")
            << withChannelField(1, QStringLiteral("source"), QStringLiteral("op.11@9"))
            << QStringLiteral("channel 2's source: 'op.11@9': the set after @ is 0..7");
        QTest::newRow("source a number")
            << withChannelField(0, QStringLiteral("source"), 515)
            << QStringLiteral("channel 1's source: expected a parameter id");
        QTest::newRow("bad colour")
            << withChannelField(3, QStringLiteral("color"), QStringLiteral("blue"))
            << QStringLiteral("channel 4's color: 'blue' is not a colour");
        QTest::newRow("unknown channel field")
            << withChannelField(0, QStringLiteral("colour"), QStringLiteral("#000000"))
            << QStringLiteral("channel 1's colour: unknown field");
        QTest::newRow("three channels")
            << [] {
                   QJsonObject root = exampleJson();
                   QJsonArray channels = root.value(QStringLiteral("channels")).toArray();
                   channels.removeLast();
                   root.insert(QStringLiteral("channels"), channels);
                   return QJsonDocument(root).toJson();
               }()
            << QStringLiteral("channels: expected 4 channels, found 3");
        QTest::newRow("trigger channel 5") << withTriggerField(QStringLiteral("channel"), 5)
                                           << QStringLiteral("trigger.channel: 5 is outside 1..4");
        QTest::newRow("trigger edge")
            << withTriggerField(QStringLiteral("edge"), QStringLiteral("up"))
            << QStringLiteral("trigger.edge: 'up': expected rising or falling");
        QTest::newRow("trigger level text")
            << withTriggerField(QStringLiteral("level"), QStringLiteral("12"))
            << QStringLiteral("trigger.level: expected a number");
        QTest::newRow("pre-trigger share")
            << withTriggerField(QStringLiteral("preTrigger"), 1.5)
            << QStringLiteral("trigger.preTrigger: 1.5 is outside 0..1");
        QTest::newRow("roll of no time") << withField(QStringLiteral("rollSeconds"), 0)
                                         << QStringLiteral("rollSeconds: 0 is outside");
        QTest::newRow("negative rate") << withField(QStringLiteral("rateLimitHz"), -1)
                                       << QStringLiteral("rateLimitHz: -1 is outside");
        QTest::newRow("no name") << withField(QStringLiteral("name"), QStringLiteral("  "))
                                 << QStringLiteral("name: give the preset a name");
        QTest::newRow("unknown field") << withField(QStringLiteral("scale"), 2)
                                       << QStringLiteral("scale: unknown field");
        QTest::newRow("key twice")
            << QByteArray("{\"format\": \"drivedesk-scope-preset\", \"version\": 1, "
                          "\"version\": 1}")
            << QStringLiteral("version: appears twice");
    }

    void aBadFileIsRefusedSayingWhatIsWrong()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.json"));
        QVERIFY(write(path, json));
        QString error;
        QVERIFY(!ScopePresetFile::load(path, &error));
        QVERIFY2(error.startsWith(QStringLiteral("preset file '%1': ").arg(path)), qPrintable(error));
        QVERIFY2(error.contains(message), qPrintable(error));
    }

    void aFileTooLargeOrNotAFileIsNotRead()
    {
        QTemporaryDir dir;
        const QString large = dir.filePath(QStringLiteral("large.json"));
        QVERIFY(write(large, QByteArray(ScopePresetFile::kMaxFileSize + 1, ' ')));
        QString error;
        QVERIFY(!ScopePresetFile::load(large, &error));
        QVERIFY2(error.contains(QStringLiteral("too large")) && error.contains(large),
                 qPrintable(error));

        // A device that never ends and a pipe no one writes to: refused, not read for ever.
        QVERIFY(!ScopePresetFile::load(QStringLiteral("/dev/zero"), &error));
        QVERIFY2(error.contains(QStringLiteral("not a regular file")), qPrintable(error));
        const QString fifo = dir.filePath(QStringLiteral("fifo.json"));
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QVERIFY(!ScopePresetFile::load(fifo, &error));
        QVERIFY2(error.contains(QStringLiteral("not a regular file")) && error.contains(fifo),
                 qPrintable(error));

        QVERIFY(!ScopePresetFile::load(dir.filePath(QStringLiteral("none.json")), &error));
        QVERIFY2(error.contains(QStringLiteral("cannot read")), qPrintable(error));
    }

    void theLibraryListsThePlantsPresetsFirstForTheDrivesKind()
    {
        QTemporaryDir dir;
        QDir(ScopePresetLibrary::userFolder()).removeRecursively();
        const QString plantFile = dir.filePath(QStringLiteral("line 4.json"));
        QCOMPARE(ScopePresetLibrary::plantFolder(plantFile),
                 dir.filePath(QStringLiteral("line 4.scope-presets")));

        ScopePreset mine = examplePreset();
        mine.name = QStringLiteral("Mine");
        QVERIFY(ScopePresetLibrary().save(mine, nullptr));
        ScopePreset other = examplePreset();
        other.name = QStringLiteral("Another drive's");
        other.driveKind = QStringLiteral("In.00=9999");
        QVERIFY(ScopePresetLibrary().save(other, nullptr));
        ScopePreset anyDrive = examplePreset();
        anyDrive.name = QStringLiteral("Any drive");
        anyDrive.driveKind.clear();
        QVERIFY(ScopePresetLibrary().save(anyDrive, nullptr));

        const ScopePresetLibrary library(plantFile);
        ScopePreset plants = examplePreset();
        plants.name = QStringLiteral("Zeta: the plant's / own");
        QString path;
        QString error;
        QVERIFY2(library.save(plants, &path, &error), qPrintable(error));
        QCOMPARE(path, dir.filePath(QStringLiteral("line 4.scope-presets/Zeta_ the plant's _ own.json")));
        QVERIFY(write(ScopePresetLibrary::userFolder() + QStringLiteral("/broken.json"), "{"));

        QStringList problems;
        const QList<ScopePresetEntry> listed = library.list(examplePreset().driveKind, &problems);
        QStringList names;
        for (const ScopePresetEntry &entry : listed)
            names << entry.preset.name + (entry.besidePlant ? QStringLiteral(" (plant)") : QString());
        QCOMPARE(names, (QStringList{QStringLiteral("Zeta: the plant's / own (plant)"),
                                     QStringLiteral("Any drive"), QStringLiteral("Mine")}));
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems.first().contains(QStringLiteral("broken.json")), qPrintable(problems.first()));
        // Without a plant, only the user's.
        QCOMPARE(ScopePresetLibrary().list(examplePreset().driveKind).size(), 2);
        QDir(ScopePresetLibrary::userFolder()).removeRecursively();
    }
};

QTEST_GUILESS_MAIN(TestScopePreset)
#include "tst_scopepreset.moc"
