#include "parameters/DriveIdentity.h"
#include "parameters/MetadataCache.h"

#include "SampleDrive.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;

namespace {

// A drive with the identification parameters of an F5 (Sy.02, Sy.03, In.00, In.06, In.07 name
// its kind; In.10 is its serial number), one set-programmable parameter and a plaintext.
DriveDescription identifiedDrive(int language = 0, qint32 softwareVersion = 180)
{
    const bool german = language == 1;
    DriveDescription drive = TestData::sample();
    drive.language = language;
    drive.identification.clear();
    drive.incompleteReason.clear();

    GroupDescription sy;
    sy.address = 0x0000;
    sy.id = QStringLiteral("Sy");
    sy.name = german ? QStringLiteral("Systemparameter") : QStringLiteral("System parameters");
    ParameterDescription identifier
        = TestData::parameter(0x0002, german ? QStringLiteral("Umrichterkennung")
                                             : QStringLiteral("Inverter identifier"));
    identifier.values[0] = 0x0F51;
    ParameterDescription powerUnit = TestData::parameter(0x0003, QStringLiteral("Power unit"));
    powerUnit.values[0] = 0;
    sy.parameters << identifier << powerUnit;

    GroupDescription in;
    in.address = 0x0E00;
    in.index = 20;
    in.id = QStringLiteral("In");
    in.name = german ? QStringLiteral("Information") : QStringLiteral("Information");
    const auto add = [&in](quint8 number, const QString &name, qint32 value) {
        ParameterDescription p = TestData::parameter(quint16(0x0E00 | number), name);
        p.values[0] = value;
        in.parameters << p;
    };
    add(0, QStringLiteral("Inverter type"), 0x0F50);
    add(6, QStringLiteral("Software version"), softwareVersion);
    add(7, QStringLiteral("Software date"), 22114);
    add(10, QStringLiteral("Serial number"), 60822465);

    GroupDescription op;
    op.address = 0x0300;
    op.index = 2;
    op.id = QStringLiteral("op");
    op.name = german ? QStringLiteral("Betriebsparameter") : QStringLiteral("Operation");
    ParameterDescription speed = TestData::parameter(
        0x030B, german ? QStringLiteral("Max. Drehzahl rechts")
                       : QStringLiteral("Maximum speed forward"));
    speed.maximum = 4000;
    speed.defaultValue = 3000;
    speed.properties1 = 1u << 11;
    for (int set = 0; set < kParameterSets; ++set)
        speed.values[set] = 3000 + set;
    speed.error = QStringLiteral("value of set 5: busy");
    PlaintextDefinition rotation;
    rotation.mask = 0xFFFFFFFF;
    rotation.entries << PlaintextEntry{0, 0, german ? QStringLiteral("aus") : QStringLiteral("off")};
    speed.plaintexts << rotation;
    op.parameters << speed;

    drive.groups = {sy, op, in};
    return drive;
}

DriveKind kindOf(const DriveDescription &drive)
{
    const std::optional<DriveKind> kind = DriveIdentity::kind(drive);
    return kind ? *kind : DriveKind{};
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(bytes) == bytes.size();
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

// The metadata cache: one file per kind of drive, nothing trusted that is not a valid file
// for the kind asked for.
class TestMetadataCache : public QObject
{
    Q_OBJECT
private slots:
    void theKindIsNamedByTheIdentificationWithoutTheSerialNumber()
    {
        const DriveDescription drive = identifiedDrive();
        const std::optional<DriveKind> kind = DriveIdentity::kind(drive);
        QVERIFY(kind);
        QCOMPARE(kind->addresses(), (QList<quint16>{0x0002, 0x0003, 0x0E00, 0x0E06, 0x0E07}));

        DriveDescription other = drive;
        other.groups[2].parameters[3].values[0] = 12345; // another serial number: same kind
        QCOMPARE(DriveIdentity::kind(other), kind);
        other.groups[2].parameters[1].values[0] = 181; // another software version
        QVERIFY(DriveIdentity::kind(other) != kind);

        DriveDescription unread = drive;
        unread.groups[2].parameters[2].values[0].reset(); // In.07 not read
        QVERIFY(!DriveIdentity::kind(unread));
        DriveDescription noInformation = drive;
        noInformation.groups.removeLast();
        QVERIFY(!DriveIdentity::kind(noInformation));
    }

    void whatIsStoredIsFoundWithoutValues()
    {
        QTemporaryDir dir;
        MetadataCache cache(dir.path());
        const DriveDescription drive = identifiedDrive();
        QString error;
        QVERIFY2(cache.store(kindOf(drive), drive, &error), qPrintable(error));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 1);

        QString warning;
        const std::optional<DriveDescription> found = cache.find(kindOf(drive), 0, &warning);
        QVERIFY(found);
        QCOMPARE(warning, QString());
        QVERIFY(found->metadataFromCache);
        QCOMPARE(found->groups.size(), drive.groups.size());
        for (qsizetype g = 0; g < drive.groups.size(); ++g) {
            const GroupDescription &stored = found->groups.at(g);
            GroupDescription expected = drive.groups.at(g);
            for (ParameterDescription &parameter : expected.parameters) {
                parameter.values = {}; // values are read from the drive, never cached
                parameter.error.clear();
            }
            QCOMPARE(stored, expected);
        }
        const ParameterDescription *speed = found->find(0x030B);
        QVERIFY(speed);
        QCOMPARE(speed->maximum, 4000);
        QCOMPARE(speed->plaintexts.constFirst().entries.constFirst().text, QStringLiteral("off"));
        QCOMPARE(speed->values[0], std::nullopt);
    }

    void anotherKindOrLanguageIsNotFound()
    {
        QTemporaryDir dir;
        MetadataCache cache(dir.path());
        const DriveDescription drive = identifiedDrive();
        QVERIFY(cache.store(kindOf(drive), drive));

        QString warning;
        const DriveKind newerSoftware = kindOf(identifiedDrive(0, 181));
        QVERIFY(!cache.find(newerSoftware, 0, &warning));
        QCOMPARE(warning, QString());
        QVERIFY(!cache.find(kindOf(drive), 1, &warning)); // German not read yet
        QCOMPARE(warning, QString());
        QVERIFY(cache.find(kindOf(drive), 0)); // and the file is still there
    }

    void eachLanguageKeepsItsTexts()
    {
        QTemporaryDir dir;
        MetadataCache cache(dir.path());
        const DriveDescription english = identifiedDrive(0);
        const DriveDescription german = identifiedDrive(1);
        QVERIFY(cache.store(kindOf(english), english));
        QVERIFY(cache.store(kindOf(german), german));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 1);
        QCOMPARE(cache.probes(), (QList<QList<quint16>>{kindOf(english).addresses()}));

        const std::optional<DriveDescription> en = cache.find(kindOf(english), 0);
        const std::optional<DriveDescription> de = cache.find(kindOf(english), 1);
        QVERIFY(en && de);
        QCOMPARE(en->find(0x030B)->name, QStringLiteral("Maximum speed forward"));
        QCOMPARE(de->find(0x030B)->name, QStringLiteral("Max. Drehzahl rechts"));
        QCOMPARE(de->language, 1);

        // A second kind: its own file, the same probe addresses listed once.
        const DriveDescription newer = identifiedDrive(0, 181);
        QVERIFY(cache.store(kindOf(newer), newer));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 2);
        QCOMPARE(cache.probes().size(), 1);
    }

    void aFileThatIsNotOneIsIgnoredRemovedAndReplaced_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("reason");
        const DriveDescription drive = identifiedDrive();
        QTest::newRow("not JSON") << QByteArray("{\"format\": \"drivedesk-metad")
                                  << QStringLiteral("not JSON");
        QTest::newRow("empty") << QByteArray() << QStringLiteral("not JSON");
        QTest::newRow("a parameter file")
            << QByteArray(R"({"format": "drivedesk-parameters", "version": 1})")
            << QStringLiteral("not a DriveDesk metadata cache file");
        QTest::newRow("a later version")
            << QByteArray(R"({"format": "drivedesk-metadata-cache", "version": 2})")
            << QStringLiteral("cache version 2");

        // A valid file of another kind under this kind's name.
        QTemporaryDir scratch;
        MetadataCache other(scratch.path());
        const DriveDescription newer = identifiedDrive(0, 181);
        other.store(kindOf(newer), newer);
        QTest::newRow("another kind inside")
            << readFile(other.filePath(kindOf(newer))) << QStringLiteral("another kind");

        // The right kind, with a language entry that is no parameter document.
        other.store(kindOf(drive), drive);
        QJsonObject root = QJsonDocument::fromJson(readFile(other.filePath(kindOf(drive)))).object();
        QJsonObject languages = root.value(QStringLiteral("languages")).toObject();
        QJsonObject english = languages.value(QStringLiteral("0")).toObject();
        english.insert(QStringLiteral("groups"), QStringLiteral("none"));
        languages.insert(QStringLiteral("0"), english);
        root.insert(QStringLiteral("languages"), languages);
        QTest::newRow("a broken language") << QJsonDocument(root).toJson()
                                           << QStringLiteral("groups");
    }

    void aFileThatIsNotOneIsIgnoredRemovedAndReplaced()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        MetadataCache cache(dir.path());
        const DriveDescription drive = identifiedDrive();
        const QString path = cache.filePath(kindOf(drive));
        QVERIFY(writeFile(path, content));

        QString warning;
        QVERIFY(!cache.find(kindOf(drive), 0, &warning));
        QVERIFY2(warning.contains(path), qPrintable(warning));
        QVERIFY2(warning.contains(reason), qPrintable(warning));
        QVERIFY(!QFile::exists(path));

        // The next complete scan writes a good one.
        QVERIFY(writeFile(path, content));
        QVERIFY(cache.store(kindOf(drive), drive));
        warning.clear();
        QVERIFY(cache.find(kindOf(drive), 0, &warning));
        QCOMPARE(warning, QString());
    }

    void aFolderThatCannotBeWrittenSaysSo()
    {
        QTemporaryDir dir;
        const QString blocker = dir.filePath(QStringLiteral("a-file"));
        QVERIFY(writeFile(blocker, "not a folder"));
        MetadataCache cache(blocker + QStringLiteral("/metadata"));
        const DriveDescription drive = identifiedDrive();
        QString error;
        QVERIFY(!cache.store(kindOf(drive), drive, &error));
        QVERIFY2(error.contains(blocker + QStringLiteral("/metadata")), qPrintable(error));
        QCOMPARE(readFile(blocker), QByteArray("not a folder"));
        QVERIFY(cache.probes().isEmpty());
        QVERIFY(!cache.find(kindOf(drive), 0));
    }

    void clearRemovesEveryKind()
    {
        QTemporaryDir dir;
        MetadataCache cache(dir.path());
        const DriveDescription drive = identifiedDrive();
        const DriveDescription newer = identifiedDrive(0, 181);
        QVERIFY(cache.store(kindOf(drive), drive));
        QVERIFY(cache.store(kindOf(newer), newer));
        QString error;
        QVERIFY2(cache.clear(&error), qPrintable(error));
        QVERIFY(cache.probes().isEmpty());
        QVERIFY(!cache.find(kindOf(drive), 0));
        QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    }

    void theDefaultFolderIsSharedByEveryFrontEnd()
    {
        QVERIFY(MetadataCache::defaultDirectory().endsWith(QStringLiteral("/DriveDesk/metadata")));
    }
};

QTEST_GUILESS_MAIN(TestMetadataCache)
#include "tst_metadatacache.moc"
