#include "plant/PlantFile.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;

namespace {

// The example of docs/plant.md, as PlantFile writes it.
const QByteArray kExample = R"({
    "format": "drivedesk-plant",
    "version": 1,
    "name": "Line 3",
    "links": [
        {
            "name": "cabinet",
            "connect": "tcp:127.0.0.1:5021",
            "protocol": "din66019ii",
            "baud": 38400,
            "addresses": [2, 5, 9]
        },
        {
            "name": "hoist",
            "connect": "serial:/dev/ttyUSB0",
            "protocol": "hsp5"
        }
    ]
}
)";

Plant examplePlant()
{
    PlantLink cabinet;
    cabinet.name = QStringLiteral("cabinet");
    cabinet.connect = QStringLiteral("tcp:127.0.0.1:5021");
    cabinet.protocol = Protocol::Din66019II;
    cabinet.baudRate = 38400;
    cabinet.addresses = {2, 5, 9};
    PlantLink hoist;
    hoist.name = QStringLiteral("hoist");
    hoist.connect = QStringLiteral("serial:/dev/ttyUSB0");
    hoist.protocol = Protocol::Hsp5;
    return Plant{QStringLiteral("Line 3"), {cabinet, hoist}};
}

// "(line L, column C)" of the first `needle` in `text`, columns counted in bytes.
QString placeOf(const QByteArray &text, const QByteArray &needle)
{
    const qsizetype at = text.indexOf(needle);
    if (at < 0)
        return QStringLiteral("needle not found: ") + QString::fromUtf8(needle);
    const QByteArray before = text.left(at);
    return QStringLiteral("(line %1, column %2)")
        .arg(before.count('\n') + 1)
        .arg(at - (before.lastIndexOf('\n') + 1) + 1);
}

} // namespace

class TestPlantFile : public QObject
{
    Q_OBJECT

private slots:
    void readsTheExample()
    {
        QString error;
        const std::optional<Plant> plant = PlantFile::fromJson(kExample, &error);
        QVERIFY2(plant, qPrintable(error));
        QCOMPARE(*plant, examplePlant());
    }

    void writesWhatItReads()
    {
        // Byte for byte: a file written once comes back unchanged.
        QCOMPARE(PlantFile::toJson(examplePlant()), kExample);
        Plant odd = examplePlant();
        odd.name = QStringLiteral("Linie \"3\" \\ Süd\t");
        odd.links[0].connect = QStringLiteral("TCP:[::1]:5021");
        odd.links[1].baudRate = 57600;
        odd.links.append({QStringLiteral("bench.2"), QStringLiteral("sim"), Protocol::Din66019,
                          std::nullopt, {}});
        const QByteArray json = PlantFile::toJson(odd);
        QString error;
        const std::optional<Plant> back = PlantFile::fromJson(json, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(*back, odd);
        QCOMPARE(PlantFile::toJson(*back), json);
    }

    void readsAnyLayout()
    {
        const QByteArray compact
            = R"({"links":[{"protocol":"DIN66019II","name":"cabinet","connect":"tcp:127.0.0.1:5021",)"
              R"("addresses":[2,5,9],"baud":38400},{"connect":"serial:/dev/ttyUSB0","name":"hoist",)"
              R"("protocol":"hsp5"}],"name":"Line 3","version":1,"format":"drivedesk-plant"})";
        QString error;
        const std::optional<Plant> plant = PlantFile::fromJson(compact, &error);
        QVERIFY2(plant, qPrintable(error));
        QCOMPARE(*plant, examplePlant());
        QCOMPARE(PlantFile::toJson(*plant), kExample);
    }

    void addressesFoundAreWrittenBack()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("line3.plant.json"));
        QVERIFY(PlantFile::save(path, examplePlant()));
        QString error;
        std::optional<Plant> plant = PlantFile::load(path, &error);
        QVERIFY2(plant, qPrintable(error));
        plant->link(QStringLiteral("cabinet"))->addresses = {2, 5, 9, 17};
        QVERIFY(PlantFile::save(path, *plant, &error));

        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> before = kExample.split('\n');
        const QList<QByteArray> after = file.readAll().split('\n');
        QCOMPARE(after.size(), before.size());
        for (qsizetype i = 0; i < before.size(); ++i) {
            if (before[i].contains("\"addresses\""))
                QCOMPARE(after[i], QByteArray("            \"addresses\": [2, 5, 9, 17]"));
            else
                QCOMPARE(after[i], before[i]);
        }
        // Searching the bus again: the addresses go, nothing else does.
        plant->link(QStringLiteral("cabinet"))->addresses.clear();
        QVERIFY(PlantFile::save(path, *plant, &error));
        const std::optional<Plant> cleared = PlantFile::load(path, &error);
        QVERIFY2(cleared, qPrintable(error));
        Plant expected = examplePlant();
        expected.links[0].addresses.clear();
        QCOMPARE(*cleared, expected);
    }

    void refusesABadFile_data()
    {
        QTest::addColumn<QByteArray>("from");
        QTest::addColumn<QByteArray>("to");
        QTest::addColumn<QByteArray>("at");
        QTest::addColumn<QString>("message");
        const auto row = [](const char *name, const char *from, const char *to, const char *at,
                            const char *message) {
            QTest::newRow(name) << QByteArray(from) << QByteArray(to) << QByteArray(at)
                                << QString::fromUtf8(message);
        };
        row("unknown key", "\"baud\": 38400,", "\"baud\": 38400, \"parity\": \"even\",",
            "\"parity\"", "links[0].parity: unknown field");
        row("unknown key at the top", "\"version\": 1,", "\"version\": 1, \"drives\": 3,",
            "\"drives\"", "drives: unknown field");
        row("wrong type", "\"baud\": 38400", "\"baud\": \"38400\"", "\"baud\"",
            "links[0].baud: expected an integer");
        row("name not a string", "\"name\": \"Line 3\"", "\"name\": 3", "\"name\"",
            "name: expected a string");
        row("links not an array", "\"links\": [", "\"links\": {\"a\": 1}, \"x\": [", "\"links\"",
            "links: expected an array");
        row("link not an object", "\"links\": [", "\"links\": [7, ", "7",
            "links[0]: expected an object");
        row("addresses not an array", "[2, 5, 9]", "2", "\"addresses\"",
            "links[0].addresses: expected an array");
        row("duplicate key", "\"protocol\": \"hsp5\"",
            "\"protocol\": \"hsp5\", \"protocol\": \"din66019\"", "\"protocol\": \"din66019\"",
            "links[1].protocol: appears twice in one object");
        row("duplicate link name", "\"name\": \"hoist\"", "\"name\": \"Cabinet\"",
            "\"name\": \"Cabinet\"", "links[1].name: 'Cabinet' is also the name of links[0]");
        row("duplicate address", "[2, 5, 9]", "[2, 5, 2]", "2]",
            "links[0].addresses[2]: drive address 2 appears twice");
        row("address out of range", "[2, 5, 9]", "[2, 240, 9]", "240",
            "links[0].addresses[1]: 240 is outside 0..239");
        row("negative address", "[2, 5, 9]", "[-1]", "-1",
            "links[0].addresses[0]: -1 is outside 0..239");
        row("address with a fraction", "[2, 5, 9]", "[2.5]", "2.5",
            "links[0].addresses[0]: expected an integer");
        row("no addresses", "[2, 5, 9]", "[]", "\"addresses\"",
            "links[0].addresses: empty: leave addresses out");
        row("addresses on HSP5", "\"protocol\": \"hsp5\"",
            "\"protocol\": \"hsp5\", \"addresses\": [1]", "\"addresses\": [1]",
            "links[1].addresses: an HSP5 link reaches one drive");
        row("connect without port", "tcp:127.0.0.1:5021", "tcp:127.0.0.1",
            "\"connect\": \"tcp:", "links[0].connect: \"127.0.0.1\" has no port");
        row("connect of no kind", "serial:/dev/ttyUSB0", "usb:/dev/ttyUSB0",
            "\"connect\": \"usb", "links[1].connect: unknown connection \"usb:/dev/ttyUSB0\"");
        row("connect without device", "serial:/dev/ttyUSB0", "serial:", "\"connect\": \"serial:",
            "links[1].connect: \"serial:\" names no serial device");
        row("unknown protocol", "\"din66019ii\"", "\"profibus\"", "\"protocol\": \"profibus\"",
            "links[0].protocol: unknown protocol 'profibus'");
        row("baud out of range", "38400", "10", "\"baud\"",
            "links[0].baud: 10 is outside 50..4000000");
        row("link name with a slash", "\"name\": \"hoist\"", "\"name\": \"../hoist\"",
            "\"name\": \"../", "links[1].name: '../hoist' cannot be part of a file name");
        row("link name with a space", "\"name\": \"hoist\"", "\"name\": \"main hoist\"",
            "\"name\": \"main", "links[1].name: 'main hoist' cannot be part of a file name");
        row("link name a device", "\"name\": \"hoist\"", "\"name\": \"NUL.x\"", "\"name\": \"NUL",
            "links[1].name: 'NUL.x' names a device on Windows");
        row("empty link name", "\"name\": \"hoist\"", "\"name\": \"\"", "\"name\": \"\"",
            "links[1].name: empty");
        row("missing field", "            \"connect\": \"serial:/dev/ttyUSB0\",\n", "",
            "{\n            \"name\": \"hoist\"", "links[1].connect: missing");
        row("missing protocol", "\"protocol\": \"din66019ii\",", "",
            "{\n            \"name\": \"cabinet\"",
            "links[0].protocol: missing");
        row("newer version", "\"version\": 1", "\"version\": 2", "\"version\"",
            "version: 2 is a newer format than this DriveDesk reads (version 1)");
        row("version zero", "\"version\": 1", "\"version\": 0", "\"version\"",
            "version: 0 is outside 1..");
        row("another format", "drivedesk-plant", "drivedesk-parameters", "\"format\"",
            "format: 'drivedesk-parameters', expected 'drivedesk-plant': not a DriveDesk plant file");
        row("empty machine name", "\"Line 3\"", "\" \"", "\"name\"", "name: empty");
        row("no links", "\"links\": [", "\"links\": [], \"x\": [", "\"links\"", "links: empty");
        // QJsonParseError's offset lies just inside the token it did not expect.
        row("not JSON", "\"version\": 1,", "\"version\": 1", "name\": \"Line", "not valid JSON: ");
        row("not an object", kExample.constData(), "\n  [1, 2]", "[", "not a DriveDesk plant file");
    }

    void refusesABadFile()
    {
        QFETCH(QByteArray, from);
        QFETCH(QByteArray, to);
        QFETCH(QByteArray, at);
        QFETCH(QString, message);
        QVERIFY(kExample.contains(from));
        QByteArray json = kExample;
        json.replace(from, to);
        QString error;
        QVERIFY(!PlantFile::fromJson(json, &error));
        QVERIFY2(error.startsWith(message), qPrintable(error));
        const QString where = placeOf(json, at);
        QVERIFY2(error.endsWith(where), qPrintable(error + QStringLiteral(" / ") + where));
    }

    void refusesWhatItCannotRead()
    {
        QTemporaryDir dir;
        QString error;
        const QString missing = dir.filePath(QStringLiteral("none.json"));
        QVERIFY(!PlantFile::load(missing, &error));
        QVERIFY2(error.contains(QStringLiteral("cannot read")) && error.contains(missing),
                 qPrintable(error));

        // A bad file named by its path, and nothing read from it.
        const QString path = dir.filePath(QStringLiteral("bad.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray(kExample).replace("[2, 5, 9]", "[2, 5, 5]"));
        file.close();
        QVERIFY(!PlantFile::load(path, &error));
        QVERIFY2(error.startsWith(path + QStringLiteral(": links[0].addresses[2]: drive address 5 "
                                                        "appears twice"))
                     && error.endsWith(QStringLiteral("(line 11, column 33)")),
                 qPrintable(error));
    }

    void linkSettings()
    {
        const Plant plant = examplePlant();
        const ConnectionSettings cabinet = plant.links[0].settings(5);
        QCOMPARE(cabinet.kind, ConnectionSettings::Kind::Tcp);
        QCOMPARE(cabinet.host, QStringLiteral("127.0.0.1"));
        QCOMPARE(cabinet.port, quint16(5021));
        QCOMPARE(cabinet.protocol, Protocol::Din66019II);
        QCOMPARE(cabinet.driveAddress, 5);
        QCOMPARE(cabinet.baudRate, 38400);
        const ConnectionSettings hoist = plant.links[1].settings(7);
        QCOMPARE(hoist.kind, ConnectionSettings::Kind::Serial);
        QCOMPARE(hoist.device, QStringLiteral("/dev/ttyUSB0"));
        QCOMPARE(hoist.protocol, Protocol::Hsp5);
        QCOMPARE(hoist.driveAddress, 1); // HSP5 has no address
        // A simulated bus holds the drives the plant names.
        PlantLink bench{QStringLiteral("bench"), QStringLiteral("sim"), Protocol::Din66019II,
                        std::nullopt, {3, 4}};
        const ConnectionSettings simulated = bench.settings(4);
        QCOMPARE(simulated.kind, ConnectionSettings::Kind::Simulated);
        QCOMPARE(simulated.simulation.driveAddresses, (QList<int>{3, 4}));
    }
};

QTEST_GUILESS_MAIN(TestPlantFile)
#include "tst_plantfile.moc"
