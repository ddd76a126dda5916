#include "link/SerialLink.h"

#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;

namespace {

// Two connected pseudo-terminals from socat: what one end sends, the other receives.
struct SocatPair {
    QTemporaryDir dir;
    QProcess socat;
    QString a() const { return dir.filePath(QStringLiteral("a")); }
    QString b() const { return dir.filePath(QStringLiteral("b")); }

    bool start()
    {
        const QString program = QStandardPaths::findExecutable(QStringLiteral("socat"));
        if (program.isEmpty())
            return false;
        socat.start(program, {QStringLiteral("-d"), QStringLiteral("-d"),
                              QStringLiteral("pty,raw,echo=0,link=%1").arg(a()),
                              QStringLiteral("pty,raw,echo=0,link=%1").arg(b())});
        return socat.waitForStarted();
    }
    // The adapter is pulled: its process ends at once, and its device nodes go with it, as
    // the system removes those of an unplugged adapter. A killed socat leaves its links
    // behind, pointing at pseudo-terminal numbers that the next pseudo-terminal opened on
    // this machine, another test's, may be given.
    void pull()
    {
        socat.kill();
        socat.waitForFinished();
        QFile::remove(a());
        QFile::remove(b());
    }
    ~SocatPair() { pull(); }
};

ConnectionSettings serialSettings(const QString &device, Protocol protocol = Protocol::Hsp5)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Serial;
    settings.device = device;
    settings.protocol = protocol;
    settings.baudRate = 38400;
    return settings;
}

} // namespace

// SerialLink on a pseudo-terminal pair: bytes through unchanged, clear reasons on failure.
class TestSerialLink : public QObject
{
    Q_OBJECT
private slots:
    void carriesBinaryBytesBothWays()
    {
        SocatPair pair;
        if (!pair.start())
            QSKIP("socat is not installed");
        QTRY_VERIFY(QFileInfo::exists(pair.a()) && QFileInfo::exists(pair.b()));

        SerialLink left(serialSettings(pair.a()));
        SerialLink right(serialSettings(pair.b()));
        QSignalSpy leftOpened(&left, &Link::opened);
        QSignalSpy rightOpened(&right, &Link::opened);
        QSignalSpy failures(&left, &Link::failed);
        left.open();
        right.open();
        QTRY_COMPARE(leftOpened.count(), 1);
        QTRY_COMPARE(rightOpened.count(), 1);
        QVERIFY(left.isOpen());
        QCOMPARE(left.description(), QStringLiteral("serial %1 38400 8E1").arg(pair.a()));

        // Every byte value, including XON/XOFF, 00h and FFh (parity marking would double it).
        QByteArray all;
        for (int i = 0; i < 256; ++i)
            all.append(char(i));
        QByteArray got;
        connect(&right, &Link::received, this, [&](const QByteArray &bytes) { got += bytes; });
        left.send(all);
        QTRY_COMPARE(got.size(), all.size());
        QCOMPARE(got, all);

        QByteArray back;
        connect(&left, &Link::received, this, [&](const QByteArray &bytes) { back += bytes; });
        right.send(QByteArrayLiteral("\x10\x80\x00\x00\x00\x46\x00\xD6"));
        QTRY_COMPARE(back, QByteArrayLiteral("\x10\x80\x00\x00\x00\x46\x00\xD6"));
        QCOMPARE(failures.count(), 0);
    }

    void missingDeviceFailsWithReason()
    {
        QTemporaryDir dir;
        const QString device = dir.filePath(QStringLiteral("no-such-port"));
        SerialLink link(serialSettings(device));
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(failed.count(), 1);
        const QString reason = failed.at(0).at(0).toString();
        QVERIFY2(reason.contains(device), qPrintable(reason));
        QVERIFY2(reason.contains(QStringLiteral("no such serial device")), qPrintable(reason));
        QCOMPARE(opened.count(), 0);
        QVERIFY(!link.isOpen());
    }

    void emptyDeviceFailsWithReason()
    {
        SerialLink link(serialSettings(QString()));
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(failed.count(), 1);
        QVERIFY2(failed.at(0).at(0).toString().contains(QStringLiteral("no serial device")),
                 qPrintable(failed.at(0).at(0).toString()));
    }

    void lostPortFailsPromptly()
    {
        SocatPair pair;
        if (!pair.start())
            QSKIP("socat is not installed");
        QTRY_VERIFY(QFileInfo::exists(pair.a()) && QFileInfo::exists(pair.b()));
        SerialLink link(serialSettings(pair.a(), Protocol::Din66019II));
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy failed(&link, &Link::failed);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        QCOMPARE(link.description(), QStringLiteral("serial %1 38400 7E1").arg(pair.a()));

        pair.pull();
        QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, 3000);
        const QString reason = failed.at(0).at(0).toString();
        QVERIFY2(reason.contains(pair.a()), qPrintable(reason));
        QVERIFY(!link.isOpen());
        QVERIFY(!QFileInfo::exists(pair.a()));
        // Reported once: the next report is that of opening the link again, on a device gone.
        link.open();
        QTRY_COMPARE(failed.count(), 2);
        const QString again = failed.at(1).at(0).toString();
        QVERIFY2(again.contains(QStringLiteral("no such serial device")), qPrintable(again));
    }

    void reopensAfterClose()
    {
        SocatPair pair;
        if (!pair.start())
            QSKIP("socat is not installed");
        QTRY_VERIFY(QFileInfo::exists(pair.a()) && QFileInfo::exists(pair.b()));
        SerialLink link(serialSettings(pair.a()));
        QSignalSpy opened(&link, &Link::opened);
        link.open();
        QTRY_COMPARE(opened.count(), 1);
        link.close();
        QVERIFY(!link.isOpen());
        link.open();
        QTRY_COMPARE(opened.count(), 2);
        QVERIFY(link.isOpen());
    }
};

QTEST_GUILESS_MAIN(TestSerialLink)
#include "tst_seriallink.moc"
