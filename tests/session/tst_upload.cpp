#include "../client/ClientTestSupport.h"

#include "bus/SimulatedBus.h"
#include "bus/SimulatorServer.h"
#include "parameters/ParameterAccess.h"
#include "parameters/ParameterDocument.h"
#include "parameters/ParameterList.h"
#include "session/UploadRun.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

namespace {

constexpr quint16 kPassword = 0x0801; // ud.01, excluded from the parameter list
constexpr quint16 kServiceCode = 0x080B; // ud.11, write only: not read, the default saved
constexpr qint32 kReadOnlyPassword = 100; // opens CpReadOnly: values of level 3 are refused

// Runs an upload to its end; `onProgress` sees each progress step.
template<typename OnProgress> UploadResult upload(DriveClient *client, OnProgress onProgress)
{
    UploadRun run(client);
    std::optional<UploadResult> result;
    QObject::connect(
        &run, &UploadRun::progress, &run,
        [&](int value, int maximum, const QString &) { onProgress(run, value, maximum); });
    QObject::connect(&run, &UploadRun::finished, &run,
                     [&](const UploadResult &finished) { result = finished; });
    run.start();
    if (!QTest::qWaitFor([&] { return result.has_value(); }, 60000)) {
        UploadResult timedOut;
        timedOut.missing << UploadGap { {}, {}, QStringLiteral("the test gave up waiting") };
        return timedOut;
    }
    return *result;
}

UploadResult upload(DriveClient *client)
{
    return upload(client, [](UploadRun &, int, int) {});
}

// Every parameter, value and what the drive says about it, read by a plain scan.
DriveDescription fullScan(DriveClient *client)
{
    QFuture<DriveDescription> future = client->scan();
    if (!waitFinished(future, 60000) || future.resultCount() == 0)
        return {};
    return future.result();
}

QString gapsText(const UploadResult &result)
{
    return result.summary() + QLatin1Char('\n') + result.details().join(QLatin1Char('\n'));
}

} // namespace

// core's upload, UploadRun, against the simulated drive: a whole read gives the parameter list
// as the drive holds it; anything less is refused, names what is missing, and saves nothing.
class TestUpload : public QObject
{
    Q_OBJECT
private slots:
    void aCompleteUploadEqualsTheDrive()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        int steps = 0;
        const UploadResult result
            = upload(s.client.get(), [&](UploadRun &, int value, int maximum) {
                  QVERIFY(value >= 0 && value <= maximum);
                  ++steps;
              });
        QVERIFY2(result.isComplete(), qPrintable(gapsText(result)));
        QVERIFY(result.missing.isEmpty());
        QVERIFY(result.summary().isEmpty());
        QVERIFY(steps > 0);

        // What a parameter list holds of the drive, parameter by parameter.
        const DriveDescription drive = fullScan(s.client.get());
        QVERIFY(drive.incompleteReason.isEmpty());
        const DriveDescription &file = result.document;
        int held = 0;
        for (const GroupDescription &group : drive.groups) {
            for (const ParameterDescription &onDrive : group.parameters) {
                const ParameterDescription *saved = file.find(onDrive.address);
                if (!ParameterList::holds(onDrive)) {
                    QVERIFY2(!saved, qPrintable(onDrive.name));
                    continue;
                }
                ++held;
                QVERIFY2(saved, qPrintable(onDrive.name));
                QVERIFY2(saved->error.isEmpty(), qPrintable(saved->error));
                ParameterDescription metadata = *saved;
                metadata.values = onDrive.values;
                QCOMPARE(metadata, onDrive);
                if (!ParameterList::isReadByUpload(onDrive))
                    QCOMPARE(saved->values, onDrive.defaultValues());
                else if (!readBackMayDiffer(onDrive)) // live values move between two reads
                    QCOMPARE(saved->values, onDrive.values);
            }
        }
        QCOMPARE(file.parameterCount(), held);
        QVERIFY(held > 150);
        QVERIFY(!file.find(kPassword));
        QVERIFY(file.find(kServiceCode));

        // Saved whole, it reads back as it was.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("drive.json"));
        QString error;
        QVERIFY2(saveUpload(path, result, &error), qPrintable(error));
        const std::optional<DriveDescription> loaded = ParameterDocument::load(path, &error);
        QVERIFY2(loaded, qPrintable(error));
        QCOMPARE(loaded->groups, file.groups);
    }

    void aRefusedReadIsNamedAndNothingIsSaved()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        // The lowest level: the drive refuses the values of the parameters above it.
        QVERIFY(s.call(s.client->writeValue(kPassword, kReadOnlyPassword, 0x01)).ok());
        const UploadResult result = upload(s.client.get());
        QCOMPARE(result.outcome, UploadResult::Outcome::Refused);
        const QStringList details = result.details();
        QVERIFY(details.size() > 100);
        // (The catalogue gives "parameters"; these tests run without one.)
        QVERIFY2(result.summary().startsWith(QString::number(details.size()))
                     && result.summary().endsWith(
                         QStringLiteral(" of the drive could not be read; nothing was saved")),
                 qPrintable(result.summary()));
        const QString maxSpeed
            = details.filter(QStringLiteral("op.11 Maximum speed forward: ")).value(0);
        QVERIFY2(maxSpeed.contains(QStringLiteral("password")), qPrintable(gapsText(result)));

        // Nothing is written, and a backup already there stays as it was.
        QTemporaryDir dir;
        const QString fresh = dir.filePath(QStringLiteral("fresh.json"));
        QString error;
        QVERIFY(!saveUpload(fresh, result, &error));
        QCOMPARE(error, result.summary());
        QVERIFY(!QFile::exists(fresh));
        const QString older = dir.filePath(QStringLiteral("older.json"));
        QFile file(older);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("an older backup");
        file.close();
        QVERIFY(!saveUpload(older, result, &error));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), QByteArray("an older backup"));
    }

    void aDriveGoingSilentPartwayIsRefused()
    {
        SimulatorServer server(Protocol::Hsp5, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        // Short timeouts, so that the stop is quick; long enough that the simulated drive,
        // which answers from this test's own thread, is not taken for silent while a busy
        // machine holds that thread up.
        ClientOptions options;
        options.timeoutMs = 250;
        options.retries = 1;
        Session s(tcpTo(server), options);
        QVERIFY(s.connected());
        QElapsedTimer silentFor;
        const UploadResult result = upload(s.client.get(), [&](UploadRun &, int value, int) {
            if (value > 400 && !server.bus().isSilent()) {
                server.bus().setSilent(true);
                silentFor.start();
            }
        });
        QVERIFY(silentFor.isValid());
        QCOMPARE(result.outcome, UploadResult::Outcome::Refused);
        QVERIFY(!result.missing.isEmpty());
        QVERIFY(result.missing.constFirst().id.isEmpty());
        QVERIFY2(result.summary().contains(QStringLiteral("stopped answering"))
                     && result.summary().contains(QStringLiteral("nothing was saved")),
                 qPrintable(result.summary()));
        // Ended at the first request given up, not after every remaining read timed out.
        QVERIFY2(silentFor.elapsed() < 5000, qPrintable(QString::number(silentFor.elapsed())));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("drive.json"));
        QVERIFY(!saveUpload(path, result));
        QVERIFY(!QFile::exists(path));
    }

    void aCancelledUploadSavesNothing()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        const UploadResult result = upload(s.client.get(), [](UploadRun &run, int value, int) {
            if (value > 100)
                run.cancel();
        });
        QCOMPARE(result.outcome, UploadResult::Outcome::Cancelled);
        QVERIFY2(result.summary().contains(QStringLiteral("cancelled"))
                     && result.summary().contains(QStringLiteral("nothing was saved")),
                 qPrintable(result.summary()));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("drive.json"));
        QVERIFY(!saveUpload(path, result));
        QVERIFY(!QFile::exists(path));
        // The client goes on: the next upload reads the whole drive.
        QVERIFY(upload(s.client.get()).isComplete());
    }

    // A read that went to the end may still miss a value: a gap is a gap.
    void aMissingValueOrDescriptionIsAGap()
    {
        DriveDescription read;
        GroupDescription group;
        group.id = QStringLiteral("op");
        group.address = 0x0300;
        ParameterDescription speed;
        speed.address = 0x030B;
        speed.name = QStringLiteral("Maximum speed forward");
        speed.properties1 = 1u << 11; // set-programmable
        for (std::size_t set = 0; set < kParameterSets; ++set)
            speed.values[set] = 3000;
        speed.values[3].reset();
        ParameterDescription period;
        period.address = 0x0305;
        period.name = QStringLiteral("Demo period");
        period.values[0] = 200;
        period.error = QStringLiteral("limits: no answer");
        group.parameters = { period, speed };
        read.groups = { group };

        const UploadResult result = checkUpload(read);
        QCOMPARE(result.outcome, UploadResult::Outcome::Refused);
        const QStringList details = result.details();
        QCOMPARE(details.size(), 2);
        QCOMPARE(details[0], QStringLiteral("op.05 Demo period: limits: no answer"));
        QVERIFY2(details[1].startsWith(QStringLiteral("op.11 Maximum speed forward: no value "
                                                      "read for set"))
                     && details[1].endsWith(QStringLiteral(" 3")),
                 qPrintable(details[1]));
        read.groups[0].parameters[0].error.clear();
        read.groups[0].parameters[1].values[3] = 3000;
        QVERIFY(checkUpload(read).isComplete());
        read.incompleteReason = QStringLiteral("link lost");
        QCOMPARE(checkUpload(read).summary(),
                 QStringLiteral("the drive could not be read to the end (link lost); nothing "
                                "was saved"));
    }

    // A live value cannot be confirmed by reading it again while it moves: a backup, which
    // restores settings, is saved without it, and the file says why it is missing.
    void anUnconfirmedLiveValueIsNoGap()
    {
        DriveDescription read;
        GroupDescription group;
        group.id = QStringLiteral("ru");
        group.address = 0x0200;
        ParameterDescription frequency;
        frequency.address = 0x0203;
        frequency.name = QStringLiteral("Actual frequency");
        frequency.properties2 = 1u << 9; // changed by the inverter
        frequency.error = QStringLiteral("value: not confirmed");
        group.parameters = { frequency };
        read.groups = { group };
        const UploadResult result = checkUpload(read);
        QVERIFY2(result.isComplete(), qPrintable(result.details().join(QLatin1Char('\n'))));
        QCOMPARE(result.document.groups[0].parameters[0].error, frequency.error);

        // A setting with the same error is a gap.
        read.groups[0].parameters[0].properties2 = 0;
        QCOMPARE(checkUpload(read).outcome, UploadResult::Outcome::Refused);
    }
};

QTEST_GUILESS_MAIN(TestUpload)
#include "tst_upload.moc"
