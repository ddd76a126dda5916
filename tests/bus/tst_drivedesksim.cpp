#include "BusTestSupport.h"
#include "link/TcpLink.h"

#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

using namespace DriveDesk;
using namespace DriveDesk::BusTest;

namespace {

const QString kProgram = QStringLiteral(DRIVEDESK_SIM_PROGRAM);

// drivedesk-sim running until the test ends.
struct Simulator {
    QProcess process;
    QString output;

    bool start(const QStringList &arguments)
    {
        process.start(kProgram, arguments);
        return process.waitForStarted();
    }
    // Waits for the "listening on" line and returns it.
    QString listeningLine()
    {
        const bool settled = QTest::qWaitFor([this] {
            output += QString::fromLocal8Bit(process.readAllStandardOutput());
            return output.contains(QStringLiteral("listening on"))
                   || process.state() == QProcess::NotRunning;
        }, 5000);
        if (!settled)
            return QString();
        for (const QString &line : output.split(QLatin1Char('\n'))) {
            if (line.contains(QStringLiteral("listening on")))
                return line;
        }
        return QString();
    }
    bool stop(int signal)
    {
        ::kill(pid_t(process.processId()), signal);
        const bool finished = process.waitForFinished(5000);
        output += QString::fromLocal8Bit(process.readAllStandardOutput());
        return finished;
    }
    ~Simulator()
    {
        if (process.state() != QProcess::NotRunning) {
            process.kill();
            process.waitForFinished();
        }
    }
};

} // namespace

// The drivedesk-sim program: where it listens, that it answers, clean stops and bad options.
class TestDrivedeskSim : public QObject
{
    Q_OBJECT
private slots:
    void printsItsAddressAndAnswersOverTcp()
    {
        Simulator sim;
        QVERIFY(sim.start({QStringLiteral("--listen"), QStringLiteral("tcp:127.0.0.1:0"),
                           QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
                           QStringLiteral("--address"), QStringLiteral("1,2"),
                           QStringLiteral("--address"), QStringLiteral("5"),
                           QStringLiteral("--latency-us"), QStringLiteral("300")}));
        const QString line = sim.listeningLine();
        const QRegularExpression pattern(QStringLiteral(
            "^drivedesk-sim: DIN66019II drives 1, 2, 5 listening on tcp:127\\.0\\.0\\.1:(\\d+)$"));
        const QRegularExpressionMatch match = pattern.match(line);
        QVERIFY2(match.hasMatch(), qPrintable(sim.output));

        ConnectionSettings settings;
        const QString target = QStringLiteral("tcp:127.0.0.1:") + match.captured(1);
        QVERIFY(settings.parseTarget(target, nullptr));
        TcpLink link(settings);
        Operator op(Protocol::Din66019II);
        QList<Telegram> replies;
        connect(&link, &Link::received, this,
                [&](const QByteArray &bytes) { replies += op.telegrams(bytes); });
        QSignalSpy opened(&link, &Link::opened);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        link.send(op.encode(readValue(kStateAddress, 3, 5)));
        QTRY_COMPARE(replies.size(), 1);
        QCOMPARE(replies[0].operatorInvoke, quint8(3));
        QCOMPARE(replies[0].ack, Ack::Ok);

        QVERIFY(sim.stop(SIGTERM));
        QCOMPARE(sim.process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(sim.process.exitCode(), 0);
        QVERIFY2(sim.output.contains(QStringLiteral("stopped")), qPrintable(sim.output));
    }

    void servesDrivesOfOtherKinds()
    {
        constexpr quint16 kSoftwareVersion = 0x0E06; // In.06
        Simulator sim;
        QVERIFY(sim.start({QStringLiteral("--listen"), QStringLiteral("tcp:127.0.0.1:0"),
                           QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
                           QStringLiteral("--address"), QStringLiteral("2,9,11"),
                           QStringLiteral("--other-kind"), QStringLiteral("9"),
                           QStringLiteral("--unidentified"), QStringLiteral("11")}));
        const QRegularExpression pattern(
            QStringLiteral("^drivedesk-sim: DIN66019II drives 2, 9 \\(other kind\\), 11 "
                           "\\(unidentified\\) listening on tcp:127\\.0\\.0\\.1:(\\d+)$"));
        const QRegularExpressionMatch match = pattern.match(sim.listeningLine());
        QVERIFY2(match.hasMatch(), qPrintable(sim.output));

        ConnectionSettings settings;
        QVERIFY(settings.parseTarget(QStringLiteral("tcp:127.0.0.1:") + match.captured(1), nullptr));
        TcpLink link(settings);
        Operator op(Protocol::Din66019II);
        QList<Telegram> replies;
        connect(&link, &Link::received, this,
                [&](const QByteArray &bytes) { replies += op.telegrams(bytes); });
        QSignalSpy opened(&link, &Link::opened);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        quint8 invoke = 0;
        for (int drive : {2, 9, 11}) {
            link.send(op.encode(readValue(kSoftwareVersion, ++invoke, drive)));
            QTRY_COMPARE(replies.size(), int(invoke));
        }
        QCOMPARE(replies[0].ack, Ack::Ok);
        QCOMPARE(replies[1].ack, Ack::Ok);
        QVERIFY(replies[0].as<ParameterValue>()->value != replies[1].as<ParameterValue>()->value);
        QVERIFY(replies[2].ack != Ack::Ok); // drive 11 has no In.06
        QVERIFY(sim.stop(SIGTERM));
    }

    void removesItsPtyLinkOnInterrupt()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("drive"));
        Simulator sim;
        QVERIFY(sim.start({QStringLiteral("--pty"), path}));
        const QString line = sim.listeningLine();
        const QString expected = QStringLiteral("drivedesk-sim: HSP5 drive 1 listening on pty:");
        QVERIFY2(line.startsWith(expected + path), qPrintable(sim.output));
        QVERIFY(QFileInfo(path).isSymLink());
        QVERIFY(sim.stop(SIGINT));
        QCOMPARE(sim.process.exitCode(), 0);
        QVERIFY(!QFileInfo(path).isSymLink());
    }

    void busyPortExits1()
    {
        QTcpServer holder;
        QVERIFY(holder.listen(QHostAddress::LocalHost, 0));
        QProcess process;
        process.start(kProgram, {QStringLiteral("--listen"),
                                 QStringLiteral("tcp:127.0.0.1:%1").arg(holder.serverPort())});
        QVERIFY(process.waitForFinished(5000));
        QCOMPARE(process.exitCode(), 1);
        const QString error = QString::fromLocal8Bit(process.readAllStandardError());
        QVERIFY2(error.contains(QStringLiteral("cannot listen")), qPrintable(error));
    }

    void badOptionsExit2_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("mentions");
        // Each row is valid but for the one option under test.
        const auto row = [](const char *name, const QString &arguments, const char *mentions) {
            QTest::newRow(name) << arguments.split(QLatin1Char(' '), Qt::SkipEmptyParts)
                                << QString::fromLatin1(mentions);
        };
        const auto with = [](const char *more) {
            return QStringLiteral("--listen tcp:127.0.0.1:0 ") + QLatin1String(more);
        };
        const auto alone = [](const char *arguments) { return QString::fromLatin1(arguments); };
        row("no transport", alone(""), "--listen tcp:HOST:PORT or --pty");
        row("two transports", with("--pty /tmp/x"), "either");
        row("not tcp", alone("--listen udp:1.2.3.4:5"), "udp:1.2.3.4:5");
        row("port", alone("--listen tcp:127.0.0.1:99999"), "99999");
        row("host", alone("--listen tcp:nohost:1"), "nohost");
        row("protocol", with("--protocol modbus"), "modbus");
        row("address range", with("--address 240"), "240");
        row("address text", with("--address one"), "one");
        row("address twice", with("--protocol din66019ii --address 3,3"), "twice");
        row("hsp5 several", with("--address 1,2"), "point to point");
        row("other kind not on the bus", with("--protocol din66019ii --address 2,5 --other-kind 9"),
            "no drive 9");
        row("unidentified not on the bus", with("--unidentified 2"), "no drive 2");
        row("unidentified range", with("--unidentified 300"), "300");
        row("two kinds", with("--protocol din66019ii --address 2,5 --other-kind 5 --unidentified 5"),
            "both");
        row("latency", with("--latency-us -1"), "--latency-us");
        row("baud", with("--baud 0"), "--baud");
        row("rate range", with("--corrupt-rate 1.5"), "--corrupt-rate");
        row("rate text", with("--drop-rate often"), "often");
        row("delay", with("--delay-ms x"), "--delay-ms");
        row("unsolicited din", with("--protocol din66019ii --unsolicited-rate 0.1"), "only HSP5");
        row("seed", with("--seed -3"), "--seed");
        row("unknown option", with("--bogus"), "bogus");
        row("missing value", with("--baud"), "baud");
        row("stray argument", with("extra"), "extra");
    }

    void badOptionsExit2()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, mentions);
        QProcess process;
        process.start(kProgram, arguments);
        QVERIFY(process.waitForFinished(5000));
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        const QString error = QString::fromLocal8Bit(process.readAllStandardError());
        QCOMPARE(process.exitCode(), 2);
        QVERIFY2(error.startsWith(QStringLiteral("drivedesk-sim: ")), qPrintable(error));
        QVERIFY2(error.contains(mentions), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestDrivedeskSim)
#include "tst_drivedesksim.moc"
