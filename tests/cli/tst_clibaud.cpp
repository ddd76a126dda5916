#include "CliTestSupport.h"

#include <QFileInfo>
#include <QTemporaryDir>

using namespace DriveDesk::CliTest;

// drivedesk-cli finds the baud rate of a drive on a serial line (--baud auto, the default
// there), against drivedesk-sim on a pseudo-terminal that answers only at its own rate.
class TestCliBaud : public QObject
{
    Q_OBJECT
private slots:
    void findsTheRateAndAFixedRateIsThatRate_data()
    {
        QTest::addColumn<QString>("protocol");
        QTest::newRow("hsp5") << QStringLiteral("hsp5");
        QTest::newRow("din66019ii") << QStringLiteral("din66019ii");
    }

    void findsTheRateAndAFixedRateIsThatRate()
    {
        QFETCH(QString, protocol);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString link = dir.filePath(QStringLiteral("drive"));
        QProcess simulator;
        simulator.start(kSim,
                        { QStringLiteral("--pty"), link, QStringLiteral("--protocol"), protocol,
                          QStringLiteral("--baud"), QStringLiteral("19200") });
        QVERIFY(simulator.waitForStarted());
        QTRY_VERIFY(QFileInfo::exists(link));
        const QStringList connection { QStringLiteral("--connect"),
                                       QStringLiteral("serial:") + link,
                                       QStringLiteral("--protocol"), protocol };
        const QString cache = dir.filePath(QStringLiteral("cache"));

        Run run = cli(connection + QStringList { QStringLiteral("read"), QStringLiteral("op.11") },
                      cache);
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.err.contains(QStringLiteral("found the drive at 19200 Bd")),
                 qPrintable(run.err));
        QVERIFY2(run.out.contains(QStringLiteral("op.11")), qPrintable(run.out));

        run = cli(connection
                      + QStringList { QStringLiteral("--baud"), QStringLiteral("19200"),
                                      QStringLiteral("read"), QStringLiteral("op.11") },
                  cache);
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(!run.err.contains(QStringLiteral("found the drive")), qPrintable(run.err));

        // A fixed rate is that rate, even where the drive is at another.
        run = cli(connection
                      + QStringList { QStringLiteral("--baud"), QStringLiteral("38400"),
                                      QStringLiteral("read"), QStringLiteral("op.11") },
                  cache);
        QVERIFY2(run.exitCode == 3, qPrintable(explain(run)));
        QVERIFY2(run.err.contains(QStringLiteral("stopped answering")), qPrintable(run.err));

        simulator.terminate();
        QVERIFY(simulator.waitForFinished());
    }
};

QTEST_GUILESS_MAIN(TestCliBaud)
#include "tst_clibaud.moc"
