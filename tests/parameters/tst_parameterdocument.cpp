#include "SampleDrive.h"
#include "parameters/ParameterDocument.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::TestData;

namespace {

QJsonObject sampleObject()
{
    return QJsonDocument::fromJson(ParameterDocument::toJson(sample())).object();
}

// The JSON with the value at `path` replaced; an undefined value removes it.
QJsonValue edited(const QJsonValue &node, QVariantList path, const QJsonValue &value)
{
    if (path.isEmpty())
        return value;
    const QVariant step = path.takeFirst();
    if (step.typeId() == QMetaType::Int) {
        QJsonArray array = node.toArray();
        if (path.isEmpty() && value.isUndefined())
            array.removeAt(step.toInt());
        else
            array[step.toInt()] = edited(array.at(step.toInt()), path, value);
        return array;
    }
    QJsonObject object = node.toObject();
    if (path.isEmpty() && value.isUndefined())
        object.remove(step.toString());
    else
        object[step.toString()] = edited(object.value(step.toString()), path, value);
    return object;
}

QByteArray sampleWith(const QVariantList &path, const QJsonValue &value)
{
    return QJsonDocument(edited(sampleObject(), path, value).toObject()).toJson();
}

QVariantList state(const QString &field)
{
    return { QStringLiteral("groups"), 1, QStringLiteral("parameters"), 0, field };
}

// The example of docs/parameter-file.md.
QByteArray documentedExample()
{
    return R"({
    "format": "drivedesk-parameters",
    "version": 1,
    "drive": {
        "protocol": "hsp5",
        "connection": "/dev/ttyUSB0",
        "address": -1,
        "language": 0,
        "identification": "",
        "incompleteReason": ""
    },
    "groups": [
        {
            "id": "ru", "index": 1, "address": 512, "name": "Run", "shortcut": "r",
            "properties": 24, "highestNumber": 43, "parameterCount": 30,
            "parameters": [
                {
                    "id": "ru.03", "address": 515, "name": "Actual frequency",
                    "min": -32000, "max": 32000, "default": 0,
                    "unit": "Hz", "decimals": 2, "setProgrammable": false, "readOnly": true,
                    "values": [-4180],
                    "properties1": 1024, "properties2": 5,
                    "scaling": {"divisor": 80, "multiplier": 1, "offset": 0, "flags": 530},
                    "plaintextIndices": {"displayIndex": 0, "displayCount": 0,
                                         "combivisIndex": 0, "combivisCount": 0},
                    "plaintextDefinitions": [],
                    "plaintexts": []
                }
            ]
        }
    ]
})";
}

// "line 18, column 43" of the first `marker` in `json`, counted independently of the reader.
QString placeOf(const QByteArray &json, const QByteArray &marker, qsizetype from = 0)
{
    const qsizetype at = json.indexOf(marker, from);
    const qsizetype lineStart = json.lastIndexOf('\n', at) + 1;
    return QStringLiteral("(line %1, column %2)")
        .arg(json.left(at).count('\n') + 1)
        .arg(at - lineStart + 1);
}

// The example with `from` replaced by `to` (the first place only).
QByteArray exampleWith(const QByteArray &from, const QByteArray &to)
{
    QByteArray json = documentedExample();
    const qsizetype at = json.indexOf(from);
    Q_ASSERT(at >= 0);
    return json.replace(at, from.size(), to);
}

} // namespace

// The parameter file as JSON: exact round trip, clear errors naming the place.
class TestParameterDocument : public QObject
{
    Q_OBJECT
private slots:
    void roundTripIsExact()
    {
        const DriveDescription drive = sample();
        const QByteArray json = ParameterDocument::toJson(drive);
        QString error;
        const std::optional<DriveDescription> back = ParameterDocument::fromJson(json, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->groups.size(), drive.groups.size());
        for (qsizetype g = 0; g < drive.groups.size(); ++g) {
            for (qsizetype p = 0; p < drive.groups[g].parameters.size(); ++p) {
                const ParameterDescription &expected = drive.groups[g].parameters[p];
                const ParameterDescription &actual = back->groups[g].parameters[p];
                QVERIFY2(actual == expected, qPrintable(expected.name));
            }
        }
        QVERIFY(*back == drive);
        QCOMPARE(ParameterDocument::toJson(*back), json);
    }

    void emptyDescriptionRoundTrips()
    {
        const DriveDescription empty;
        const std::optional<DriveDescription> back
            = ParameterDocument::fromJson(ParameterDocument::toJson(empty));
        QVERIFY(back);
        QVERIFY(*back == empty);
    }

    void documentedExampleLoads()
    {
        const QByteArray json = documentedExample();
        QString error;
        const std::optional<DriveDescription> drive = ParameterDocument::fromJson(json, &error);
        QVERIFY2(drive, qPrintable(error));
        const ParameterDescription *hz = drive->find(0x0203);
        QVERIFY(hz);
        QCOMPARE(hz->values[0], -4180);
        QVERIFY(!hz->values[1]);
        QCOMPARE(hz->scaling.address, quint16(0x0203));
        QCOMPARE(drive->groups.first().shortcut, 'r');
    }

    void fileHasTheDocumentedNames()
    {
        const QJsonObject root = sampleObject();
        QCOMPARE(root.value(QStringLiteral("format")).toString(),
                 QStringLiteral("drivedesk-parameters"));
        QCOMPARE(root.value(QStringLiteral("version")).toInt(), 1);
        const QJsonObject drive = root.value(QStringLiteral("drive")).toObject();
        QCOMPARE(drive.value(QStringLiteral("protocol")).toString(), QStringLiteral("hsp5"));
        QCOMPARE(drive.value(QStringLiteral("address")).toInt(), 1);

        const QJsonObject ru = root.value(QStringLiteral("groups")).toArray().at(1).toObject();
        QCOMPARE(ru.value(QStringLiteral("id")).toString(), QStringLiteral("ru"));
        QCOMPARE(ru.value(QStringLiteral("index")).toInt(), 1);
        QCOMPARE(ru.value(QStringLiteral("address")).toInt(), 0x0200);
        QCOMPARE(ru.value(QStringLiteral("shortcut")).toString(), QStringLiteral("ä"));
        const QJsonArray parameters = ru.value(QStringLiteral("parameters")).toArray();

        const QJsonObject state = parameters.at(0).toObject();
        QCOMPARE(state.value(QStringLiteral("id")).toString(), QStringLiteral("ru.0"));
        QCOMPARE(state.value(QStringLiteral("min")).toInteger(), qint64(kMin));
        QCOMPARE(state.value(QStringLiteral("max")).toInteger(), qint64(kMax));
        QCOMPARE(state.value(QStringLiteral("default")).toInt(), -1);
        QCOMPARE(state.value(QStringLiteral("properties1")).toInteger(), qint64(0xFFFFFFFF));
        QCOMPARE(state.value(QStringLiteral("setProgrammable")).toBool(), true);
        QCOMPARE(state.value(QStringLiteral("readOnly")).toBool(), false);
        QCOMPARE(state.value(QStringLiteral("error")).toString(),
                 QStringLiteral("set 1: data invalid"));
        const QJsonArray values = state.value(QStringLiteral("values")).toArray();
        QCOMPARE(values.size(), 8);
        QVERIFY(values.at(1).isNull()); // a failed read, never a guessed number
        QCOMPARE(values.at(3).toInteger(), qint64(kMin));
        const QJsonArray plaintexts = state.value(QStringLiteral("plaintexts")).toArray();
        QCOMPARE(plaintexts.size(), 5);
        QCOMPARE(plaintexts.at(2).toObject().value(QStringLiteral("text")).toString(),
                 QStringLiteral("forward"));
        QCOMPARE(plaintexts.at(2).toObject().value(QStringLiteral("value")).toInt(), 2);
        QCOMPARE(plaintexts.at(2).toObject().value(QStringLiteral("definition")).toInt(), 1);
        QCOMPARE(state.value(QStringLiteral("plaintextDefinitions")).toArray().size(), 4);

        const QJsonObject hz = parameters.at(1).toObject();
        QCOMPARE(hz.value(QStringLiteral("id")).toString(), QStringLiteral("ru.3"));
        QCOMPARE(hz.value(QStringLiteral("unit")).toString(), QStringLiteral("Hz"));
        QCOMPARE(hz.value(QStringLiteral("decimals")).toInt(), 2);
        QCOMPARE(hz.value(QStringLiteral("readOnly")).toBool(), true);
        QVERIFY(!hz.contains(QStringLiteral("error")));
        const QJsonObject scaling = hz.value(QStringLiteral("scaling")).toObject();
        QCOMPARE(scaling.value(QStringLiteral("divisor")).toInt(), 80);
        QVERIFY(!scaling.contains(QStringLiteral("address"))); // the parameter's own

        const QJsonObject bus = root.value(QStringLiteral("groups"))
                                    .toArray()
                                    .at(0)
                                    .toObject()
                                    .value(QStringLiteral("parameters"))
                                    .toArray()
                                    .at(0)
                                    .toObject();
        QCOMPARE(bus.value(QStringLiteral("values")).toArray(), (QJsonArray { 3 }));
        QCOMPARE(bus.value(QStringLiteral("id")).toString(), QStringLiteral("Sy.7"));
    }

    void hostileInputIsRefusedWithItsPlace_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        const QByteArray good = ParameterDocument::toJson(sample());
        QTest::newRow("truncated")
            << good.left(good.size() / 2) << QStringLiteral("not valid JSON: ");
        QTest::newRow("empty") << QByteArray() << QStringLiteral("not valid JSON: ");
        QTest::newRow("binary") << QByteArray("\x00\xFF\xFE{", 4)
                                << QStringLiteral("not valid JSON: ");
        QTest::newRow("array") << QByteArray("[1, 2]")
                               << QStringLiteral("not a DriveDesk parameter file: the document is "
                                                 "not a JSON object");
        QTest::newRow("format") << sampleWith({ QStringLiteral("format") }, QStringLiteral("csv"))
                                << QStringLiteral("not a DriveDesk parameter file: format is "
                                                  "'csv', expected 'drivedesk-parameters'");
        QTest::newRow("no format")
            << sampleWith({ QStringLiteral("format") }, QJsonValue::Undefined)
            << QStringLiteral("not a DriveDesk parameter file: format is "
                              "missing or not a string, expected "
                              "'drivedesk-parameters'");
        QTest::newRow("version 2") << sampleWith({ QStringLiteral("version") }, 2)
                                   << QStringLiteral("version: 2 is a newer format than this "
                                                     "DriveDesk reads (version 1)");
        QTest::newRow("version 0") << sampleWith({ QStringLiteral("version") }, 0)
                                   << QStringLiteral("version: 0 is not supported (this DriveDesk "
                                                     "reads version 1)");
        QTest::newRow("version text")
            << sampleWith({ QStringLiteral("version") }, QStringLiteral("1"))
            << QStringLiteral("version: missing or not a number");
        QTest::newRow("no drive") << sampleWith({ QStringLiteral("drive") }, QJsonValue::Undefined)
                                  << QStringLiteral("drive: missing");
        QTest::newRow("drive address")
            << sampleWith({ QStringLiteral("drive"), QStringLiteral("address") }, 300)
            << QStringLiteral("drive.address: 300 is outside -1..255");
        QTest::newRow("groups object") << sampleWith({ QStringLiteral("groups") }, QJsonObject())
                                       << QStringLiteral("groups: expected an array");
        QTest::newRow("group number") << sampleWith({ QStringLiteral("groups"), 0 }, 5)
                                      << QStringLiteral("groups[0]: expected an object");
        QTest::newRow("min text") << sampleWith(state(QStringLiteral("min")), QStringLiteral("12"))
                                  << QStringLiteral("ru.00, min: expected an "
                                                    "integer");
        QTest::newRow("min fraction") << sampleWith(state(QStringLiteral("min")), 1.5)
                                      << QStringLiteral("ru.00, min: expected an "
                                                        "integer");
        QTest::newRow("min too big")
            << sampleWith(state(QStringLiteral("min")), qint64(3000000000))
            << QStringLiteral("ru.00, min: 3000000000 is outside "
                              "-2147483648..2147483647");
        QTest::newRow("min huge") << sampleWith(state(QStringLiteral("min")), 1e300)
                                  << QStringLiteral("ru.00, min: expected an "
                                                    "integer");
        QTest::newRow("min missing")
            << sampleWith(state(QStringLiteral("min")), QJsonValue::Undefined)
            << QStringLiteral("ru.00, min: missing");
        QTest::newRow("min null") << sampleWith(state(QStringLiteral("min")), QJsonValue::Null)
                                  << QStringLiteral("ru.00, min: expected an "
                                                    "integer");
        QTest::newRow("properties negative")
            << sampleWith(state(QStringLiteral("properties1")), -1)
            << QStringLiteral("ru.00, properties1: -1 is outside 0..4294967295");
        QTest::newRow("seven values")
            << sampleWith(state(QStringLiteral("values")), QJsonArray { 1, 2, 3, 4, 5, 6, 7 })
            << QStringLiteral("ru.00, values: 7 entries; a set-programmable "
                              "parameter has one for each of the 8 sets");
        QTest::newRow("one value for eight sets")
            << sampleWith(state(QStringLiteral("values")), QJsonArray { 1 })
            << QStringLiteral("ru.00, values: 1 entries; a set-programmable "
                              "parameter has one for each of the 8 sets");
        QTest::newRow("value text")
            << sampleWith({ QStringLiteral("groups"), 1, QStringLiteral("parameters"), 0,
                            QStringLiteral("values"), 2 },
                          QStringLiteral("x"))
            << QStringLiteral("ru.00, set 2: expected an integer");
        QTest::newRow("misspelt field")
            << sampleWith(state(QStringLiteral("valeus")), QJsonArray())
            << QStringLiteral("ru.00, valeus: unknown field");
        QTest::newRow("divisor") << sampleWith(
            { QStringLiteral("groups"), 1, QStringLiteral("parameters"), 0,
              QStringLiteral("scaling"), QStringLiteral("divisor") },
            40000)
                                 << QStringLiteral(
                                        "ru.00, scaling.divisor: 40000 is outside "
                                        "-32768..32767");
        QTest::newRow("readOnly edited alone")
            << sampleWith(state(QStringLiteral("readOnly")), true)
            << QStringLiteral("ru.00, readOnly: true does not agree with "
                              "properties2 bit 3");
        QTest::newRow("unit edited alone")
            << sampleWith(state(QStringLiteral("unit")), QStringLiteral("V"))
            << QStringLiteral("ru.00, unit: 'V' does not agree with "
                              "scaling.flags (unit '')");
        QTest::newRow("id for another address")
            << sampleWith(state(QStringLiteral("id")), QStringLiteral("ru.04"))
            << QStringLiteral("ru.00, id: 'ru.04' names 0204h, not the address "
                              "0200h");
        QTest::newRow("id for no group")
            << sampleWith(state(QStringLiteral("id")), QStringLiteral("zz.0"))
            << QStringLiteral("ru.00, id: no group 'zz' on this drive");
        QTest::newRow("plaintext definition")
            << sampleWith({ QStringLiteral("groups"), 1, QStringLiteral("parameters"), 0,
                            QStringLiteral("plaintexts"), 0, QStringLiteral("definition") },
                          9)
            << QStringLiteral("ru.00, plaintexts[0].definition: 9, but "
                              "plaintextDefinitions has 4 entries");
        QTest::newRow("plaintext text missing")
            << sampleWith({ QStringLiteral("groups"), 1, QStringLiteral("parameters"), 0,
                            QStringLiteral("plaintexts"), 1, QStringLiteral("text") },
                          QJsonValue::Undefined)
            << QStringLiteral("ru.00, plaintexts[1].text: missing");
        QTest::newRow("address outside group")
            << sampleWith(state(QStringLiteral("address")), 0x0300)
            << QStringLiteral("groups[1].parameters[0].address: 0300h is not in group ru (0200h)");
        QTest::newRow("duplicate group") << sampleWith(
            { QStringLiteral("groups"), 2, QStringLiteral("id") }, QStringLiteral("ru"))
                                         << QStringLiteral("groups[2].id: 'ru' appears twice");
        const QJsonValue first = sampleObject()
                                     .value(QStringLiteral("groups"))
                                     .toArray()
                                     .at(1)
                                     .toObject()
                                     .value(QStringLiteral("parameters"))
                                     .toArray()
                                     .at(0);
        QTest::newRow("duplicate parameter")
            << sampleWith({ QStringLiteral("groups"), 1, QStringLiteral("parameters"), 1 }, first)
            << QStringLiteral("ru.00, address: 0200h appears twice");
        // Found by fuzz_parameterfile: such a file loaded, and saved with ids it refuses.
        QTest::newRow("group id with a tab")
            << sampleWith({ QStringLiteral("groups"), 0, QStringLiteral("id") },
                          QStringLiteral("u\tF"))
            << QStringLiteral("groups[0].id: 'u\tF' cannot stand in a parameter id");
        QTest::newRow("group id with a dot")
            << sampleWith({ QStringLiteral("groups"), 0, QStringLiteral("id") },
                          QStringLiteral("S.y"))
            << QStringLiteral("groups[0].id: 'S.y' cannot stand in a parameter id");
        QTest::newRow("shortcut") << sampleWith(
            { QStringLiteral("groups"), 0, QStringLiteral("shortcut") }, QStringLiteral("ab"))
                                  << QStringLiteral(
                                         "groups[0].shortcut: 'ab' is not one Latin-1 character");
        QTest::newRow("name number")
            << sampleWith({ QStringLiteral("groups"), 0, QStringLiteral("name") }, 5)
            << QStringLiteral("groups[0].name: expected a string");
        QTest::newRow("setProgrammable text")
            << sampleWith(state(QStringLiteral("setProgrammable")), QStringLiteral("yes"))
            << QStringLiteral("ru.00, setProgrammable: expected true or false");
    }

    void hostileInputIsRefusedWithItsPlace()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        QString actual;
        QVERIFY(!ParameterDocument::fromJson(json, &actual));
        QVERIFY2(actual.startsWith(error), qPrintable(actual));
    }

    // What no drive can hold is refused with the place, its line and its column: a key given
    // twice (JSON readers keep one of them, silently), limits the wrong way round, a default
    // outside constant limits.
    void impossibleFilesAreRefusedAtTheirLineAndColumn_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        QTest::addColumn<QString>("place");
        const QByteArray twiceMin = exampleWith("\"min\": -32000,", "\"min\": -32000, \"min\": 5,");
        QTest::newRow("key twice in a parameter")
            << twiceMin << QStringLiteral("groups[0].parameters[0].min: appears twice")
            << placeOf(twiceMin, "\"min\": 5");
        const QByteArray twiceVersion = exampleWith("\"version\": 1,", "\"version\": 1,\n    \"version\": 1,");
        QTest::newRow("key twice at the top")
            << twiceVersion << QStringLiteral("version: appears twice")
            << placeOf(twiceVersion, "\"version\"", twiceVersion.indexOf("\"version\"") + 1);
        const QByteArray twiceFlags
            = exampleWith("\"flags\": 530}", "\"flags\": 530, \"flags\": 18}");
        QTest::newRow("key twice in scaling")
            << twiceFlags << QStringLiteral("groups[0].parameters[0].scaling.flags: appears twice")
            << placeOf(twiceFlags, "\"flags\": 18");
        const QByteArray twiceLanguage
            = exampleWith("\"language\": 0,", "\"language\": 0, \"lan\\u0067uage\": 1,");
        QTest::newRow("key twice, once escaped")
            << twiceLanguage << QStringLiteral("drive.language: appears twice")
            << placeOf(twiceLanguage, "\"lan\\u0067uage\"");
        const QByteArray maxBelowMin = exampleWith("\"max\": 32000", "\"max\": -32001");
        QTest::newRow("max below min")
            << maxBelowMin
            << QStringLiteral("ru.03, max: -32001 is below min -32000")
            << placeOf(maxBelowMin, "\"max\"");
        const QByteArray defaultAbove = exampleWith("\"default\": 0", "\"default\": 32001");
        QTest::newRow("default above constant max")
            << defaultAbove
            << QStringLiteral("ru.03, default: 32001 is outside min..max "
                              "(-32000..32000)")
            << placeOf(defaultAbove, "\"default\"");
        const QByteArray defaultBelow = exampleWith("\"default\": 0", "\"default\": -32001");
        QTest::newRow("default below constant min")
            << defaultBelow
            << QStringLiteral("ru.03, default: -32001 is outside min..max")
            << placeOf(defaultBelow, "\"default\"");
        // The reader's other faults name their line too: the field, or the object lacking it.
        const QByteArray minText = exampleWith("\"min\": -32000", "\"min\": \"low\"");
        QTest::newRow("wrong type")
            << minText << QStringLiteral("ru.03, min: expected an integer")
            << placeOf(minText, "\"min\"");
        const QByteArray noName = exampleWith("\"name\": \"Actual frequency\",", "");
        const QByteArray valueText = exampleWith("\"values\": [-4180]", "\"values\": [\"x\"]");
        QTest::newRow("value not a number")
            << valueText << QStringLiteral("ru.03, set 0: expected an integer")
            << placeOf(valueText, "\"x\"");
        QTest::newRow("missing field")
            << noName << QStringLiteral("ru.03, name: missing")
            << placeOf(noName, "{", noName.indexOf("\"parameters\""));
    }

    void impossibleFilesAreRefusedAtTheirLineAndColumn()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        QFETCH(QString, place);
        QString actual;
        QVERIFY(!ParameterDocument::fromJson(json, &actual));
        QVERIFY2(actual.startsWith(error), qPrintable(actual));
        QVERIFY2(actual.endsWith(place), qPrintable(actual + QLatin1String(" / ") + place));
    }

    // What a drive can hold loads: limits and a default that follow other parameters
    // (properties 1 bits 12-15, bit 18) may leave the default outside the limits read, and a
    // backup keeps a value outside its limits as the drive held it.
    void whatADriveCanHoldLoads_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<quint16>("address");
        QTest::addColumn<qint32>("value");
        QTest::newRow("value outside its limits")
            << exampleWith("\"values\": [-4180]", "\"values\": [-40000]") << quint16(0x0203)
            << qint32(-40000);
        QByteArray variableDefault
            = exampleWith("\"properties1\": 1024", "\"properties1\": 263168"); // bit 18
        QTest::newRow("variable default outside the limits")
            << variableDefault.replace("\"default\": 0", "\"default\": 40000")
            << quint16(0x0203) << qint32(-4180);
        QByteArray variableMax
            = exampleWith("\"properties1\": 1024", "\"properties1\": 33792"); // bit 15: always
        QTest::newRow("default above a variable max")
            << variableMax.replace("\"default\": 0", "\"default\": 40000") << quint16(0x0203)
            << qint32(-4180);
        QTest::newRow("min equal to max")
            << exampleWith("\"max\": 32000", "\"max\": -32000").replace("\"default\": 0",
                                                                       "\"default\": -32000")
            << quint16(0x0203) << qint32(-4180);
    }

    void whatADriveCanHoldLoads()
    {
        QFETCH(QByteArray, json);
        QFETCH(quint16, address);
        QFETCH(qint32, value);
        QString error;
        const std::optional<DriveDescription> drive = ParameterDocument::fromJson(json, &error);
        QVERIFY2(drive, qPrintable(error));
        QCOMPARE(drive->find(address)->values[0], value);
    }

    void parseErrorsGiveLineAndColumn()
    {
        QString error;
        QVERIFY(!ParameterDocument::fromJson("{\n  \"format\": \"drivedesk-parameters\",\n  x\n}",
                                             &error));
        QVERIFY2(error.contains(QStringLiteral("line 3")), qPrintable(error));
    }

    // What fuzz_parameterfile found: every file loads, exactly, or is refused with a reason.
    void fuzzCorpusReplays()
    {
        const QDir corpus(QStringLiteral(DRIVEDESK_TEST_DATA "/fuzz/parameterfile"));
        const QStringList files = corpus.entryList(QDir::Files);
        QVERIFY2(files.size() >= 4, qPrintable(corpus.path()));
        int loaded = 0;
        for (const QString &name : files) {
            QFile file(corpus.filePath(name));
            QVERIFY(file.open(QIODevice::ReadOnly));
            QString error;
            const std::optional<DriveDescription> drive
                = ParameterDocument::fromJson(file.readAll(), &error);
            if (!drive) {
                QVERIFY2(!error.isEmpty(), qPrintable(name));
                continue;
            }
            ++loaded;
            QVERIFY2(error.isEmpty(), qPrintable(name + QLatin1String(": ") + error));
            const QByteArray saved = ParameterDocument::toJson(*drive);
            const std::optional<DriveDescription> again
                = ParameterDocument::fromJson(saved, &error);
            QVERIFY2(again, qPrintable(name + QLatin1String(": ") + error));
            QVERIFY2(*again == *drive, qPrintable(name));
        }
        QVERIFY(loaded > 0); // the valid seeds
    }
};

QTEST_GUILESS_MAIN(TestParameterDocument)
#include "tst_parameterdocument.moc"