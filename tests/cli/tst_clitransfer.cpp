#include "CliTestSupport.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <sys/stat.h>

using namespace DriveDesk::CliTest;

namespace {

// Changes one parameter of a parameter file as `edit` says; false when the file or the
// parameter is not there.
template<typename Edit>
bool editParameter(const QString &path, const QString &id, Edit edit)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
    file.close();
    QJsonArray groups = root.value(QStringLiteral("groups")).toArray();
    bool found = false;
    for (qsizetype g = 0; g < groups.size(); ++g) {
        QJsonObject group = groups[g].toObject();
        QJsonArray parameters = group.value(QStringLiteral("parameters")).toArray();
        for (qsizetype p = 0; p < parameters.size(); ++p) {
            QJsonObject parameter = parameters[p].toObject();
            if (parameter.value(QStringLiteral("id")).toString() != id)
                continue;
            edit(parameter);
            parameters[p] = parameter;
            found = true;
        }
        group.insert(QStringLiteral("parameters"), parameters);
        groups[g] = group;
    }
    root.insert(QStringLiteral("groups"), groups);
    return found && file.open(QIODevice::WriteOnly | QIODevice::Truncate)
        && file.write(QJsonDocument(root).toJson()) > 0;
}

// Changes one raw value of a parameter file as an editor would.
bool editFile(const QString &path, const QString &id, int set, int raw)
{
    return editParameter(path, id, [set, raw](QJsonObject &parameter) {
        QJsonArray values = parameter.value(QStringLiteral("values")).toArray();
        values[set] = raw;
        parameter.insert(QStringLiteral("values"), values);
    });
}

} // namespace

// drivedesk-cli upload, download and diff with the drive, against a simulated drive that keeps
// what each command wrote.
class TestCliTransfer : public QObject
{
    Q_OBJECT
private slots:
    void init()
    {
        m_server = std::make_unique<SimulatorProcess>();
        QVERIFY2(m_server->started(), qPrintable(m_server->error()));
        QVERIFY(m_dir.isValid());
        m_file = m_dir.filePath(QStringLiteral("drive.json"));
        const Run upload = drive({QStringLiteral("upload"), m_file});
        QVERIFY2(upload.exitCode == 0, qPrintable(explain(upload)));
        QVERIFY2(upload.out.contains(QStringLiteral("195 parameters")), qPrintable(upload.out));
        QVERIFY2(upload.out.contains(QStringLiteral("1 write-only with the default")), qPrintable(upload.out));
    }

    void cleanup() { m_server.reset(); }

    void theDriveComesBackFromItsFile()
    {
        Run run = drive({QStringLiteral("write"), QStringLiteral("op.11"), QStringLiteral("2500"),
                         QStringLiteral("--sets"), QStringLiteral("2")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));

        run = drive({QStringLiteral("diff"), QStringLiteral("drive"), m_file});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral("op.11 +Maximum speed forward +2 +2500 1/min +3000 1/min"))),
                 qPrintable(run.out));

        run = drive({QStringLiteral("download"), m_file, QStringLiteral("--dry-run")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("op.11  Maximum speed forward, set 2: 2500 1/min -> 3000 1/min")),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("nothing was written")), qPrintable(run.out));
        QVERIFY(readSet(QStringLiteral("op.11"), 2).contains(QStringLiteral("2500 1/min")));

        run = drive({QStringLiteral("download"), m_file});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("op.11  Maximum speed forward: set 2: 3000 1/min")),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("0 refused")), qPrintable(run.out));
        QVERIFY(readSet(QStringLiteral("op.11"), 2).contains(QStringLiteral("3000 1/min")));
        run = drive({QStringLiteral("diff"), QStringLiteral("drive"), m_file});
        QVERIFY2(!run.out.contains(QStringLiteral("op.11")), qPrintable(run.out));
    }

    // "Does the drive still match its backup?": live values move on (Sy.32, the scope timer,
    // counts every millisecond), settings do not; only a changed setting is a difference.
    void theDriveMatchesItsBackupWhileLiveValuesChange()
    {
        QFile file(m_file);
        QVERIFY(file.open(QIODevice::ReadOnly));
        qint64 timer = -1;
        const QJsonArray groups = QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("groups")).toArray();
        for (const QJsonValue &group : groups) {
            for (const QJsonValue &parameter : group.toObject().value(QStringLiteral("parameters")).toArray()) {
                if (parameter.toObject().value(QStringLiteral("id")).toString() == QLatin1String("Sy.32"))
                    timer = parameter.toObject().value(QStringLiteral("values")).toArray().at(0).toInteger(-1);
            }
        }
        QVERIFY2(timer >= 0, "Sy.32 in the file");
        Run run = drive({QStringLiteral("read"), QStringLiteral("Sy.32")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(!run.out.contains(QStringLiteral("(raw %1,").arg(timer)), qPrintable(run.out));

        run = drive({QStringLiteral("diff"), m_file, QStringLiteral("drive")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.startsWith(QStringLiteral("0 differences")), qPrintable(run.out));
        run = drive({QStringLiteral("diff"), QStringLiteral("drive"), m_file, QStringLiteral("--format"),
                     QStringLiteral("json")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(QJsonDocument::fromJson(run.out.toUtf8()).object().value(QStringLiteral("differences")).toArray().size(),
                 0);

        run = drive({QStringLiteral("write"), QStringLiteral("op.11"), QStringLiteral("2500"),
                     QStringLiteral("--sets"), QStringLiteral("2")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        run = drive({QStringLiteral("diff"), m_file, QStringLiteral("drive")});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral("op.11 +Maximum speed forward +2 +3000 1/min +2500 1/min"))),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("1 difference")), qPrintable(run.out));
    }

    void aFileOfAnotherDriveIsRefusedAndNothingIsWritten()
    {
        QVERIFY(editFile(m_file, QStringLiteral("In.6"), 0, 170)); // software 1.70
        QVERIFY(editFile(m_file, QStringLiteral("op.11"), 4, 2222));
        Run run = drive({QStringLiteral("download"), m_file});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("In.06 Software version is 1.70 in the file, 1.82 on the drive")),
                 qPrintable(run.err));
        QVERIFY2(run.err.contains(QStringLiteral("nothing was written")), qPrintable(run.err));
        QVERIFY(readSet(QStringLiteral("op.11"), 4).contains(QStringLiteral("3000 1/min")));

        run = drive({QStringLiteral("download"), m_file, QStringLiteral("--force"), QStringLiteral("--sets"),
                      QStringLiteral("4")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.err.contains(QStringLiteral("warning: the file was made for another drive")), qPrintable(run.err));
        QVERIFY(readSet(QStringLiteral("op.11"), 4).contains(QStringLiteral("2222 1/min")));
    }

    // A drive with no identification parameters takes its own backup, matched by its
    // metadata; a file whose metadata differs is refused, naming where it first differs.
    void anUnidentifiedDriveTakesAFileOfItsMetadata()
    {
        SimulatorProcess bus({QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
                              QStringLiteral("--address"), QStringLiteral("9,11"),
                              QStringLiteral("--other-kind"), QStringLiteral("9"),
                              QStringLiteral("--unidentified"), QStringLiteral("11")});
        QVERIFY2(bus.started(), qPrintable(bus.error()));
        const QString cacheHome = m_dir.filePath(QStringLiteral("cache"));
        const auto on = [&bus, &cacheHome](int address, const QStringList &command) {
            return cli(QStringList{QStringLiteral("--connect"), bus.target(), QStringLiteral("--protocol"),
                                   QStringLiteral("din66019ii"), QStringLiteral("--address"),
                                   QString::number(address), QStringLiteral("--quiet")}
                           + command,
                       cacheHome);
        };
        const QString own = m_dir.filePath(QStringLiteral("unidentified.json"));
        const QString other = m_dir.filePath(QStringLiteral("other-kind.json"));
        Run run = on(11, {QStringLiteral("upload"), own});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        run = on(9, {QStringLiteral("upload"), other});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        run = on(11, {QStringLiteral("write"), QStringLiteral("op.11"), QStringLiteral("2500"),
                      QStringLiteral("--sets"), QStringLiteral("2")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));

        run = on(11, {QStringLiteral("download"), own});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.err.isEmpty(), qPrintable(run.err)); // no problem, not even a warning
        QVERIFY2(run.out.contains(QStringLiteral("op.11  Maximum speed forward: set 2: 3000 1/min")),
                 qPrintable(run.out));

        run = on(11, {QStringLiteral("download"), other});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("refused: the drive has no identification, and the file's "
                                                 "metadata is not the drive's: In.00 ")),
                 qPrintable(run.err));
        QVERIFY2(run.err.contains(QStringLiteral(" is in the file, not on the drive")), qPrintable(run.err));

        // One limit of its own backup changed: another kind of drive, however alike.
        QVERIFY(editFile(own, QStringLiteral("op.11"), 2, 2222));
        QVERIFY(editParameter(own, QStringLiteral("op.11"), [](QJsonObject &parameter) {
            parameter.insert(QStringLiteral("max"), 5000);
        }));
        run = on(11, {QStringLiteral("download"), own});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("op.11 Maximum speed forward: upper limit is 5000 1/min in "
                                                 "the file, 4000 1/min on the drive")),
                 qPrintable(run.err));
        run = on(11, {QStringLiteral("read"), QStringLiteral("op.11"), QStringLiteral("--set"),
                      QStringLiteral("2")});
        QVERIFY2(run.out.contains(QStringLiteral("3000 1/min")), qPrintable(explain(run)));
        // The cache holds drive 9's kind only: a drive that names no kind is never served.
        QCOMPARE(QDir(cacheHome + QStringLiteral("/DriveDesk/metadata")).entryList(QDir::Files).size(), 1);
    }

    void aValueTheDriveRefusesIsReportedInWords()
    {
        QVERIFY(editFile(m_file, QStringLiteral("op.11"), 1, 9999)); // above 4000
        Run run = drive({QStringLiteral("download"), m_file});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("op.11 (set 1) 9999 1/min is outside 0 1/min .. 4000 1/min")),
                 qPrintable(run.err));
        run = drive({QStringLiteral("download"), m_file, QStringLiteral("--force")});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.out.contains(QStringLiteral("Refused:\n  op.11  Maximum speed forward: set 1: drive refused")),
                 qPrintable(run.out));
    }

    void theDefaultsAreASide()
    {
        Run run = drive({QStringLiteral("write"), QStringLiteral("dr.04"), QStringLiteral("300"),
                         QStringLiteral("--sets"), QStringLiteral("all")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        run = drive({QStringLiteral("diff"), QStringLiteral("defaults"), QStringLiteral("drive")});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral("dr.04 +Rated motor voltage +0 +400 V +300 V"))),
                 qPrintable(run.out));
        QVERIFY2(!run.out.contains(QStringLiteral("ru.")), qPrintable(run.out)); // live values are no setting
        // The file was made before: the simulated drive's error counters are its only values
        // off their defaults.
        run = cli({QStringLiteral("diff"), m_file, QStringLiteral("defaults")});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.out.contains(QStringLiteral("In.26")) && !run.out.contains(QStringLiteral("dr.04")),
                 qPrintable(run.out));
    }

    // A file that is not a whole, valid parameter file is refused before the drive is asked
    // anything, and the drive keeps its values.
    void aCorruptFileChangesNothing_data()
    {
        QTest::addColumn<QByteArray>("change");
        QTest::addColumn<QString>("message");
        QTest::newRow("truncated") << QByteArray("truncate") << QStringLiteral("line");
        QTest::newRow("wrong type") << QByteArray("\"min\": 0,") << QStringLiteral("expected an integer");
        QTest::newRow("newer version") << QByteArray("\"version\": 1") << QStringLiteral("newer format");
        QTest::newRow("duplicate parameter") << QByteArray("duplicate") << QStringLiteral("twice");
        QTest::newRow("key twice") << QByteArray("key twice")
                                   << QStringLiteral("groups[0].name: appears twice in one object (line ");
        QTest::newRow("max below min") << QByteArray("max below min")
                                       << QStringLiteral("ru.00, max: -1 is below min 0 (line ");
        // A bad value is named as the window names it: the parameter and the set.
        QTest::newRow("value not a number") << QByteArray("value text")
                                            << QStringLiteral("op.11, set 6: expected an integer (line ");
    }

    void aCorruptFileChangesNothing()
    {
        QFETCH(QByteArray, change);
        QFETCH(QString, message);
        QVERIFY(editFile(m_file, QStringLiteral("op.11"), 6, 2000)); // what a download would write
        QFile file(m_file);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QByteArray bytes = file.readAll();
        file.close();
        if (change == "truncate") {
            bytes.truncate(bytes.size() / 2);
        } else if (change == "duplicate") {
            const qsizetype start = bytes.indexOf("{", bytes.indexOf("\"parameters\": ["));
            const qsizetype end = bytes.indexOf("\n                },", start) + 19;
            bytes.insert(start, bytes.mid(start, end - start));
        } else if (change == "key twice") {
            const qsizetype at = bytes.indexOf("\"name\": ");
            bytes.insert(at, "\"name\": \"again\", ");
        } else if (change == "max below min") {
            const qsizetype at = bytes.indexOf("\"max\": ");
            bytes.replace(at, bytes.indexOf(',', at) - at, "\"max\": -1");
        } else if (change == "value text") {
            qsizetype at = bytes.indexOf("\"values\": [", bytes.indexOf("\"id\": \"op.11\""));
            at = bytes.indexOf('[', at) + 1;
            for (int set = 0; set < 6; ++set)
                at = bytes.indexOf(',', at) + 1;
            while (bytes.at(at) == ' ' || bytes.at(at) == '\n')
                ++at;
            bytes.replace(at, bytes.indexOf(',', at) - at, "\"fast\"");
        } else if (change.startsWith("\"min")) {
            const qsizetype at = bytes.indexOf(change);
            bytes.replace(at, change.size(), "\"min\": \"zero\",");
        } else {
            bytes.replace(change, "\"version\": 2");
        }
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(bytes);
        file.close();
        // The download, its dry run and a diff with the drive all refuse it, naming the place.
        for (const QStringList &command :
             { QStringList { QStringLiteral("download"), m_file },
               QStringList { QStringLiteral("download"), m_file, QStringLiteral("--dry-run") },
               QStringList { QStringLiteral("diff"), m_file, QStringLiteral("drive") } }) {
            const Run run = drive(command);
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(run.err.contains(m_file) && run.err.contains(message), qPrintable(run.err));
            QVERIFY2(run.out.isEmpty(), qPrintable(run.out));
        }
        QVERIFY(readSet(QStringLiteral("op.11"), 6).contains(QStringLiteral("3000 1/min")));
    }

    // A device or a pipe given as a file would never end (/dev/zero grows the memory by the
    // second, a FIFO without writer waits for ever): refused at once, nothing sent.
    void aFileThatIsNoRegularFileIsRefusedAtOnce_data()
    {
        QTest::addColumn<QString>("path");
        QTest::newRow("/dev/zero") << QStringLiteral("/dev/zero");
        QTest::newRow("/dev/urandom") << QStringLiteral("/dev/urandom");
        QTest::newRow("fifo") << QStringLiteral("fifo");
        QTest::newRow("folder") << QStringLiteral("folder");
    }

    void aFileThatIsNoRegularFileIsRefusedAtOnce()
    {
        QFETCH(QString, path);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        if (path == QLatin1String("fifo")) {
            path = dir.filePath(QStringLiteral("values.json"));
            QVERIFY(::mkfifo(QFile::encodeName(path).constData(), 0600) == 0);
        } else if (path == QLatin1String("folder")) {
            path = dir.path();
        }
        const QString plant = dir.filePath(QStringLiteral("plant.json"));
        for (const QStringList &command :
             { QStringList { QStringLiteral("download"), path, QStringLiteral("--dry-run") },
               QStringList { QStringLiteral("diff"), path, QStringLiteral("drive") } }) {
            const Run run = drive(command);
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(run.err.contains(path), qPrintable(explain(run)));
            QVERIFY2(run.out.isEmpty(), qPrintable(run.out));
        }
        const Run offline = cli({QStringLiteral("diff"), path, m_file});
        QCOMPARE(offline.exitCode, 2);
        QVERIFY2(offline.err.contains(path), qPrintable(explain(offline)));
        const Run plantRun = cli({QStringLiteral("plant"), QStringLiteral("verify"), path,
                                  dir.path()});
        QCOMPARE(plantRun.exitCode, 2);
        QVERIFY2(plantRun.err.contains(path), qPrintable(explain(plantRun)));
    }

    // A backup with holes is no backup: values the drive refuses (its lowest password level)
    // are named, and no file is written, not even over an older one.
    void anIncompleteReadWritesNoFile()
    {
        const QString path = m_dir.filePath(QStringLiteral("part.json"));
        Run run = drive({QStringLiteral("--password"), QStringLiteral("100"),
                         QStringLiteral("upload"), path});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(QRegularExpression(
                     QStringLiteral("not read: op.11 Maximum speed forward: .*password"))),
                 qPrintable(run.err));
        QVERIFY2(run.err.contains(QStringLiteral("could not be read; nothing was saved")),
                 qPrintable(run.err));
        QVERIFY(!QFile::exists(path));

        QFile older(m_file);
        QVERIFY(older.open(QIODevice::ReadOnly));
        const QByteArray before = older.readAll();
        older.close();
        run = drive({QStringLiteral("upload"), m_file}); // the level stays where it was
        QCOMPARE(run.exitCode, 1);
        QVERIFY(older.open(QIODevice::ReadOnly));
        QCOMPARE(older.readAll(), before);
    }

    void argumentsAreChecked_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        QTest::newRow("upload without file") << QStringList{QStringLiteral("--connect"), QStringLiteral("sim"), QStringLiteral("upload")}
                                             << QStringLiteral("upload takes a parameter file");
        QTest::newRow("dry run of a scan") << QStringList{QStringLiteral("--connect"), QStringLiteral("sim"), QStringLiteral("scan"), QStringLiteral("--dry-run")}
                                           << QStringLiteral("--dry-run and --force belong to download");
        QTest::newRow("drive without connection") << QStringList{QStringLiteral("diff"), QStringLiteral("drive"), QStringLiteral("a.json")}
                                                  << QStringLiteral("needs --connect");
        QTest::newRow("missing file") << QStringList{QStringLiteral("--connect"), QStringLiteral("sim"), QStringLiteral("download"), QStringLiteral("/nonexistent/x.json")}
                                      << QStringLiteral("/nonexistent/x.json");
    }

    void argumentsAreChecked()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const Run run = cli(arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(message), qPrintable(run.err));
    }

private:
    Run drive(const QStringList &command) const
    {
        return cli(QStringList{QStringLiteral("--connect"), m_server->target(), QStringLiteral("--quiet")} + command);
    }

    QString readSet(const QString &id, int set) const
    {
        const Run run = drive({QStringLiteral("read"), id, QStringLiteral("--set"), QString::number(set)});
        return run.out;
    }

    std::unique_ptr<SimulatorProcess> m_server;
    QTemporaryDir m_dir;
    QString m_file;
};

QTEST_GUILESS_MAIN(TestCliTransfer)
#include "tst_clitransfer.moc"
