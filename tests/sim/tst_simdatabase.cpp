#include "SimRequests.h"
#include "sim/CsvTable.h"
#include "sim/DatabaseLoader.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::Sim;
using namespace SimRequests;

namespace {

bool copyResources(const QString &to)
{
    for (const QString &name : QDir(resourceDirectory()).entryList(QDir::Files)) {
        QFile::remove(to + QLatin1Char('/') + name);
        if (!QFile::copy(resourceDirectory() + QLatin1Char('/') + name,
                         to + QLatin1Char('/') + name))
            return false;
        QFile::setPermissions(to + QLatin1Char('/') + name, QFile::ReadOwner | QFile::WriteOwner);
    }
    return true;
}

bool append(const QString &path, const QByteArray &text)
{
    QFile file(path);
    if (!file.open(QIODevice::Append))
        return false;
    return file.write(text) == text.size();
}

} // namespace

// The simulated drive's data: built from keb_f5_params.csv and the simulator's own tables,
// without problems; bad data is reported by name; padding to thousands of parameters.
class TestSimDatabase : public QObject
{
    Q_OBJECT
private slots:
    void shippedDataHasNoProblems()
    {
        const auto db = standardDatabase();
        QVERIFY2(db->problems().isEmpty(), qPrintable(db->problems().join(QLatin1Char('\n'))));
        QVERIFY(db->groups().size() >= 12);
        QVERIFY(db->parameters().size() >= 200);
    }

    void everyF5RowOfTheFactsIsAParameter()
    {
        const auto db = standardDatabase();
        const CsvTable facts
            = CsvTable::read(resourceDirectory() + QStringLiteral("/keb_f5_params.csv"));
        QVERIFY(facts.problems().isEmpty());
        QCOMPARE(facts.rows().size(), 114);
        int inDrive = 0;
        for (const CsvTable::Row &row : facts.rows()) {
            const QString group = facts.cell(row, QStringLiteral("group"));
            const bool f5Group
                = std::any_of(db->groups().begin(), db->groups().end(), [&](const SimGroup &g) {
                      return QString::fromLatin1(g.id.data(), 2) == group;
                  });
            if (!f5Group)
                continue;
            const quint16 address
                = quint16(facts.cell(row, QStringLiteral("address_hex")).toUInt(nullptr, 16));
            QVERIFY2(db->find(address), qPrintable(facts.cell(row, QStringLiteral("address_hex"))));
            ++inDrive;
        }
        QVERIFY(inDrive > 80);
        // The rest is left out on purpose, and said so: operator, CP, elevator firmware, G6.
        QCOMPARE(db->notes().size(), 114 - inDrive);
        for (const QString &note : db->notes())
            QVERIFY(note.contains(QLatin1String("left out")));

        const SimParameter *state = db->find(0x0200);
        QVERIFY(state);
        QCOMPARE(state->name[0], QByteArray("Inverter state"));
        QVERIFY(db->find(0x0002)); // Sy.02
        QVERIFY(db->find(0x0E19)->isSetProgrammable()); // In.25
        QCOMPARE(db->find(0x0007)->defaultValue, 3); // Sy.07 9600 baud
    }

    // The facts write limits as their sources did: decimal ("65535", "130.0") unless they cannot
    // be ("7FFF", "7FFFh"). Every limit they give is the simulated drive's limit.
    void everyLimitOfTheFactsIsTheDrivesLimit()
    {
        const auto db = standardDatabase();
        const CsvTable facts
            = CsvTable::read(resourceDirectory() + QStringLiteral("/keb_f5_params.csv"));
        const QRegularExpression decimal(QStringLiteral("^(-?\\d+)(?:\\.(\\d+))?$"));
        int checked = 0;
        for (const CsvTable::Row &row : facts.rows()) {
            const quint16 address
                = quint16(facts.cell(row, QStringLiteral("address_hex")).toUInt(nullptr, 16));
            const SimParameter *parameter = db->find(address);
            if (!parameter)
                continue;
            const int decimals = facts.cell(row, QStringLiteral("decimals")).toInt();
            const std::pair<const char *, qint32> limits[] = {
                { "min", parameter->minimum },
                { "max", parameter->maximum },
                { "default", parameter->defaultValue },
            };
            for (const auto &[column, actual] : limits) {
                QString text = facts.cell(row, QString::fromLatin1(column));
                if (text.isEmpty())
                    continue;
                qint64 expected = 0;
                const QRegularExpressionMatch match = decimal.match(text);
                if (match.hasMatch()) {
                    const QString fraction = match.captured(2).leftJustified(decimals, u'0');
                    QVERIFY2(fraction.size() == decimals, qPrintable(text));
                    expected = (match.captured(1) + fraction).toLongLong();
                } else {
                    if (text.endsWith(u'h'))
                        text.chop(1);
                    bool ok = false;
                    expected = text.toLongLong(&ok, 16);
                    QVERIFY2(ok, qPrintable(text));
                }
                const QString what = QStringLiteral("%1.%2 %3 \"%4\"")
                                         .arg(facts.cell(row, QStringLiteral("group")),
                                              facts.cell(row, QStringLiteral("number")),
                                              QString::fromLatin1(column),
                                              facts.cell(row, QString::fromLatin1(column)));
                QVERIFY2(actual == expected,
                         qPrintable(QStringLiteral("%1: the drive has %2").arg(what).arg(actual)));
                ++checked;
            }
        }
        QVERIFY(checked > 100);
        QCOMPARE(db->find(0x0404)->maximum, 0xFFF); // Pn.04, the simulator's own hex limits
        QCOMPARE(db->find(0x0508)->maximum, 4095); // uF.08
        QCOMPARE(db->find(0x0E19)->maximum, 0xFFFF); // In.25
        QCOMPARE(db->find(0x0010)->maximum, 0x7FFF); // Sy.16
    }

    void csvErrorsNameFileAndLine()
    {
        CsvTable table = CsvTable::parse(QStringLiteral("a,b\n1,\"x, y\"\n2\n# comment\n3,4\n"),
                                         QStringLiteral("t.csv"));
        QCOMPARE(table.rows().size(), 2);
        QCOMPARE(table.cell(table.rows().at(0), QStringLiteral("b")), QStringLiteral("x, y"));
        QCOMPARE(table.problems(),
                 QStringList { QStringLiteral("t.csv:3: 1 cells, the header has 2") });

        table = CsvTable::parse(QStringLiteral("a,b\n1,\"open\n"), QStringLiteral("u.csv"));
        QCOMPARE(table.problems(),
                 QStringList { QStringLiteral("u.csv:2: unterminated quoted cell") });

        table = CsvTable::read(QStringLiteral("/nonexistent/x.csv"));
        QCOMPARE(table.problems().size(), 1);
        QVERIFY(table.problems().first().startsWith(
            QLatin1String("/nonexistent/x.csv: cannot be read")));
    }

    void badDataIsReportedByName()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QVERIFY(copyResources(dir.path()));
        QVERIFY(append(dir.filePath(QStringLiteral("sim_f5_parameters.csv")),
                       "op,90,A name much longer than twenty-four,Kurz,furlong,0,10,0,0,,,,,,,\n"
                       "op,91,Fine,Fein,,0,10,20,0,,q,,,nosuchtexts,nosuchsignal,\n"
                       "op,92,No limits,Keine Grenzen,,,,0,0,,,,,,,\n"
                       "op,93,Texts,,,0,1,0,0,,,,,badtext,,\n"
                       "zz,1,Nowhere,Nirgends,,0,1,0,0,,,,,,,\n"));
        QVERIFY(append(dir.filePath(QStringLiteral("sim_f5_plaintexts.csv")),
                       "unused,,,,0,oFF,off,aus\n"
                       "badtext,,,,0,,Gr\xc3\xbc\x65n,gruen\n"));
        const auto db = loadDatabase(dir.path());
        const QString problems = db->problems().join(QLatin1Char('\n'));
        for (const char *expected :
             { "op.90: English name \"A name much longer than twenty-four\" is longer than 24",
               "op.90: unknown unit \"furlong\"", "op.91: default 20 outside 0..10",
               "op.91: unknown flag 'q'", "op.91: unknown plaintexts \"nosuchtexts\"",
               "op.91: unknown signal \"nosuchsignal\"", "op.92: no limits",
               "op.93: a name is missing", "English text \"Gr\u00fcen\" is not 7-bit ASCII",
               "unknown group \"zz\"", "plaintexts \"unused\" are used by no parameter" })
            QVERIFY2(problems.contains(QString::fromUtf8(expected)), qPrintable(problems));
        // The parameters are still there, so that nothing vanishes unnoticed.
        QVERIFY(db->find(0x035A));
        QCOMPARE(db->find(0x035A)->name[0].size(), 24);
    }

    void paddingReaches5000Parameters()
    {
        SimulatedDrive drive({ 1, 5000, 1 });
        QCOMPARE(drive.parameterCount(), 5000);
        QVERIFY(drive.groupCount() > 16);
        // A scan sees them all: every group's count matches names that answer.
        int names = 0;
        for (int page = 0; page < 0x80; ++page) {
            const Telegram g = drive.respond(
                read(Service::GroupProperties, GroupPropertiesData { quint16(page << 8) }), 0);
            if (g.ack != Ack::Ok)
                continue;
            int inGroup = 0;
            for (int number = 0; number <= g.as<GroupPropertiesData>()->highestNumber; ++number) {
                const Telegram n = drive.respond(
                    read(Service::ParameterName, NameData { quint16(page << 8 | number), 1, {} }),
                    0);
                if (n.ack == Ack::Ok) {
                    ++inGroup;
                    QVERIFY(!n.as<NameData>()->text.isEmpty());
                }
            }
            QCOMPARE(inGroup, g.as<GroupPropertiesData>()->countMinusOne + 1);
            names += inGroup;
        }
        QCOMPARE(names, 5000);
        // Generated parameters behave like the others.
        QCOMPARE(drive.respond(readValue(0x2000), 0).ack, Ack::Ok);
        QCOMPARE(drive.respond(read(Service::Limits, ParameterLimits { 0x2000 }), 0).ack, Ack::Ok);
    }

    void paddingIsDeterministicPerSeed()
    {
        SimulatedDrive a({ 1, 3000, 1 });
        SimulatedDrive b({ 1, 3000, 1 });
        SimulatedDrive c({ 1, 3000, 2 });
        int differences = 0;
        for (quint16 address = 0x2000; address < 0x2000 + 200; ++address) {
            const Telegram request = read(Service::Limits, ParameterLimits { address });
            QCOMPARE(a.respond(request, 0), b.respond(request, 0));
            if (a.respond(request, 0) != c.respond(request, 0))
                ++differences;
        }
        QVERIFY(differences > 0);
    }

    void paddingBelowOrFarAboveTheStandardDrive()
    {
        const int standard = SimulatedDrive().parameterCount();
        QCOMPARE(SimulatedDrive({ 1, 10, 1 }).parameterCount(), standard);
        QCOMPARE(SimulatedDrive({ 1, 1000000, 1 }).parameterCount(), standard + 96 * 200);
    }
};

QTEST_GUILESS_MAIN(TestSimDatabase)
#include "tst_simdatabase.moc"
