#include "bus/LinkFactory.h"
#include "monitor/TelegramMonitor.h"
#include "monitor/TrafficFilterModel.h"
#include "monitor/TrafficModel.h"
#include "parameters/DriveDescription.h"

#include "client/DriveClient.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QFile>
#include <QIcon>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QScrollBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QTreeView>

#include <memory>

using namespace DriveDesk;

namespace {

constexpr int kWaitMs = 15000;
constexpr quint16 kMaxSpeedForward = 0x030B; // op.11 of the simulated F5, 8 sets
constexpr quint16 kMotorVoltage = 0x0604; // dr.04 of the simulated F5, 8 sets
constexpr quint16 kActualLoad = 0x020D; // ru.13 of the simulated F5, "Actual load" in %

ConnectionSettings simulated(Protocol protocol, SimulationOptions simulation = {})
{
    simulation.replyLatencyUs = 0;
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.protocol = protocol;
    settings.simulation = simulation;
    return settings;
}

bool connectClient(DriveClient &client)
{
    client.connectToDrive();
    return QTest::qWaitFor([&] { return client.state() == DriveClient::State::Connected; },
                           kWaitMs);
}

bool finished(const QFuture<Reply> &future)
{
    return QTest::qWaitFor([&] { return future.isFinished(); }, kWaitMs);
}

TrafficRecord record(TrafficRecord::Kind kind, qint64 msecs, const QByteArray &bytes,
                     const QString &meaning)
{
    TrafficRecord r;
    r.kind = kind;
    r.msecsSinceEpoch = msecs;
    r.bytes = bytes;
    r.meaning = meaning;
    return r;
}

QString cell(const QAbstractItemModel &model, int row, int column)
{
    return model.index(row, column).data().toString();
}

// The rows whose direction column reads `direction`.
QList<int> rowsOf(const QAbstractItemModel &model, const QString &direction)
{
    QList<int> rows;
    for (int row = 0; row < model.rowCount(); ++row) {
        if (cell(model, row, TrafficModel::DirectionColumn) == direction)
            rows << row;
    }
    return rows;
}

// The meanings of the rows whose direction column reads `direction`.
QStringList meaningsOf(const QAbstractItemModel &model, const QString &direction)
{
    QStringList meanings;
    for (int row : rowsOf(model, direction))
        meanings << cell(model, row, TrafficModel::MeaningColumn);
    return meanings;
}

// Every text through the translator comes out marked: what the monitor shows untranslated
// is what a catalogue could never reach.
class MarkingTranslator : public QTranslator
{
public:
    static constexpr QChar kMark = QChar(0x00A4);
    bool isEmpty() const override { return false; }
    QString translate(const char *, const char *source, const char *, int) const override
    {
        return kMark + QString::fromUtf8(source);
    }
};

} // namespace

// The telegram monitor dock: rows from a real client on the simulated drive, errors, filter,
// pause, the bounded list, saving and copying.
class TestTelegramMonitor : public QObject
{
    Q_OBJECT
private:
    std::unique_ptr<TelegramMonitor> m_monitor;
    std::unique_ptr<QAbstractItemModelTester> m_modelTester;
    std::unique_ptr<QAbstractItemModelTester> m_filterTester;

    TrafficModel &model() { return *m_monitor->model(); }

    // `count` records, one a millisecond from `from`, shown at once.
    void feed(int count, qint64 from = 0, TrafficRecord::Kind kind = TrafficRecord::Kind::Sent)
    {
        for (int i = 0; i < count; ++i)
            model().append(record(kind, from + i, QByteArray::number(from + i),
                                  QStringLiteral("telegram %1").arg(from + i)));
        model().flush();
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true); // the dock's column widths go to QSettings
    }

    void init()
    {
        m_monitor = std::make_unique<TelegramMonitor>();
        using Mode = QAbstractItemModelTester::FailureReportingMode;
        m_modelTester
            = std::make_unique<QAbstractItemModelTester>(m_monitor->model(), Mode::QtTest);
        m_filterTester
            = std::make_unique<QAbstractItemModelTester>(m_monitor->filterModel(), Mode::QtTest);
    }

    void cleanup()
    {
        m_filterTester.reset();
        m_modelTester.reset();
        m_monitor.reset();
    }

    void readsOfARealClientShowAsRows_data()
    {
        QTest::addColumn<QString>("protocol");
        QTest::newRow("hsp5") << QStringLiteral("hsp5");
        QTest::newRow("din66019ii") << QStringLiteral("din66019ii");
    }
    void readsOfARealClientShowAsRows()
    {
        QFETCH(QString, protocol);
        const Protocol spoken = *protocolFromName(protocol);
        DriveClient client(simulated(spoken), everyLink());
        m_monitor->attach(&client);
        QVERIFY(connectClient(client));
        QVERIFY(finished(client.readValue(kMaxSpeedForward, 0x01)));
        QVERIFY(finished(client.readValue(kMotorVoltage, 0x01)));

        const QAbstractItemModel &shown = *m_monitor->filterModel();
        QTRY_VERIFY(rowsOf(shown, QStringLiteral("← drive")).size() >= 2);
        const QList<int> sent = rowsOf(shown, QStringLiteral("→ drive"));
        const QList<int> received = rowsOf(shown, QStringLiteral("← drive"));
        QVERIFY(sent.size() >= 2);
        QVERIFY(rowsOf(shown, QStringLiteral("error")).isEmpty());
        QVERIFY(cell(shown, sent.first(), TrafficModel::TimeColumn)
                    .contains(
                        QRegularExpression(QStringLiteral("^\\d\\d:\\d\\d:\\d\\d\\.\\d\\d\\d$"))));
        for (int row : sent + received) {
            QVERIFY(
                cell(shown, row, TrafficModel::BytesColumn)
                    .contains(QRegularExpression(QStringLiteral("^[0-9A-F]{2}( [0-9A-F]{2})+$"))));
            QVERIFY(!cell(shown, row, TrafficModel::MeaningColumn).isEmpty());
            QVERIFY(!shown.index(row, 0).data(Qt::BackgroundRole).isValid());
        }
        const auto meaningNames = [&](quint16 address) {
            const QString hex
                = QStringLiteral("%1h").arg(address, 4, 16, QLatin1Char('0')).toUpper();
            for (int row : sent) {
                if (cell(shown, row, TrafficModel::MeaningColumn)
                        .contains(hex, Qt::CaseInsensitive))
                    return true;
            }
            return false;
        };
        QVERIFY(meaningNames(kMaxSpeedForward));
        QVERIFY(meaningNames(kMotorVoltage));

        // The ASCII protocol also reads as characters, control characters named.
        const bool ascii = spoken != Protocol::Hsp5;
        QCOMPARE(m_monitor->view()->isColumnHidden(TrafficModel::CharactersColumn), !ascii);
        const QString answer = cell(shown, received.last(), TrafficModel::CharactersColumn);
        const QString request = cell(shown, sent.last(), TrafficModel::CharactersColumn);
        if (ascii) {
            QVERIFY2(answer.startsWith(QStringLiteral("<STX>"))
                         && answer.contains(QStringLiteral("<ETX>")),
                     qPrintable(answer));
            QVERIFY2(request.contains(QStringLiteral("<ENQ>")), qPrintable(request));
            QVERIFY(shown.index(received.last(), TrafficModel::BytesColumn)
                        .data(Qt::ToolTipRole)
                        .toString()
                        .contains(QStringLiteral("<STX>")));
        } else {
            QVERIFY(answer.isEmpty());
        }

        // Detached, the client's traffic no longer arrives.
        m_monitor->attach(nullptr);
        const int rows = model().rowCount();
        QSignalSpy traffic(&client, &DriveClient::traffic);
        QVERIFY(finished(client.readValue(kMaxSpeedForward, 0x01)));
        QTRY_VERIFY(traffic.size() >= 2);
        model().flush();
        QCOMPARE(model().rowCount(), rows);
        QCOMPARE(model().waitingCount(), 0);
    }

    void anErrorIsHighlightedAndPassesErrorsOnly()
    {
        SimulationOptions faults;
        faults.corruptByteRate = 0.05;
        faults.seed = 3;
        ClientOptions options;
        options.timeoutMs = 30;
        DriveClient client(simulated(Protocol::Din66019II, faults), everyLink(), options);
        m_monitor->attach(&client);
        QVERIFY(connectClient(client));
        const auto errorRows = [this] { return rowsOf(model(), QStringLiteral("error")); };
        const auto answerRows = [this] { return rowsOf(model(), QStringLiteral("← drive")); };
        for (int i = 0; i < 200 && (errorRows().isEmpty() || answerRows().isEmpty()); ++i) {
            QVERIFY(finished(client.readValue(kMaxSpeedForward, 0x01)));
            model().flush();
        }
        QVERIFY2(!errorRows().isEmpty(), "a corrupted answer should show as an error");

        const int error = errorRows().first();
        const QModelIndex direction = model().index(error, TrafficModel::DirectionColumn);
        QVERIFY(direction.data(Qt::BackgroundRole).canConvert<QColor>());
        QVERIFY(!direction.data(Qt::DecorationRole).value<QIcon>().isNull());
        QVERIFY(!cell(model(), error, TrafficModel::MeaningColumn).isEmpty());
        const QList<int> good = answerRows();
        QVERIFY(!good.isEmpty());
        QVERIFY(!model().index(good.first(), 0).data(Qt::BackgroundRole).isValid());

        m_monitor->setErrorsOnly(true);
        const QAbstractItemModel &shown = *m_monitor->filterModel();
        QCOMPARE(shown.rowCount(), errorRows().size());
        QCOMPARE(rowsOf(shown, QStringLiteral("error")).size(), shown.rowCount());
        QVERIFY(m_monitor->statusText().contains(QStringLiteral(" of ")));
        m_monitor->setErrorsOnly(false);
        QCOMPARE(shown.rowCount(), model().rowCount());
    }

    void theFilterSearchesMeaningBytesAndCharacters()
    {
        model().append(record(TrafficRecord::Kind::Sent, 1, QByteArray::fromHex("024731"),
                              QStringLiteral("read 030Bh set 1")));
        model().setProtocol(Protocol::Din66019II);
        model().append(record(TrafficRecord::Kind::Received, 2, QByteArray("\x02G1\x03", 4),
                              QStringLiteral("answer")));
        model().flush();
        const QAbstractItemModel &shown = *m_monitor->filterModel();

        const auto matches = [&](const QString &text) {
            m_monitor->setFilterText(text);
            QStringList meanings;
            for (int row = 0; row < shown.rowCount(); ++row)
                meanings << cell(shown, row, TrafficModel::MeaningColumn);
            return meanings;
        };
        QCOMPARE(matches(QStringLiteral("030bh")),
                 QStringList { QStringLiteral("read 030Bh set 1") });
        QCOMPARE(matches(QStringLiteral("47 31")).size(), 2);
        QCOMPARE(matches(QStringLiteral("4731")).size(), 2);
        QCOMPARE(matches(QStringLiteral("2473")), QStringList()); // not on a byte boundary
        QCOMPARE(matches(QStringLiteral("<etx>")), QStringList { QStringLiteral("answer") });
        QCOMPARE(matches(QStringLiteral("  ")).size(), 2);
    }

    void pauseHoldsTelegramsAndShowsThemOnResume()
    {
        feed(3);
        m_monitor->setPaused(true);
        QVERIFY(m_monitor->isPaused());
        for (int i = 0; i < 5; ++i)
            model().append(
                record(TrafficRecord::Kind::Received, 100 + i, "x", QStringLiteral("held")));
        QTRY_VERIFY2(m_monitor->statusText().contains(QStringLiteral("5 telegram")),
                     qPrintable(m_monitor->statusText()));
        QVERIFY(m_monitor->statusText().contains(QStringLiteral("held")));
        QCOMPARE(model().rowCount(), 3);
        QCOMPARE(model().waitingCount(), 5);

        m_monitor->setPaused(false);
        QCOMPARE(model().rowCount(), 8);
        QCOMPARE(model().waitingCount(), 0);
        QCOMPARE(cell(model(), 7, TrafficModel::MeaningColumn), QStringLiteral("held"));
        QVERIFY(!m_monitor->statusText().contains(QStringLiteral("held")));
        QCOMPARE(model().droppedCount(), 0);

        m_monitor->clear();
        QCOMPARE(model().rowCount(), 0);
        QCOMPARE(model().receivedCount(), 0);
    }

    void pausedBeyondTheCapacityCountsWhatIsDropped()
    {
        model().setCapacity(10);
        m_monitor->setPaused(true);
        feed(25);
        QCOMPARE(model().rowCount(), 0);
        QCOMPARE(model().waitingCount(), 10);
        QCOMPARE(model().droppedCount(), 15);
        m_monitor->setPaused(false);
        QCOMPARE(model().rowCount(), 10);
        QCOMPARE(model().entry(0).record.msecsSinceEpoch, 15);
        QVERIFY2(m_monitor->statusText().contains(QStringLiteral("15 older telegram")),
                 qPrintable(m_monitor->statusText()));
    }

    void theOldestAreDroppedBeyondTheCapacityAndCounted()
    {
        model().setCapacity(100);
        feed(60);
        feed(190, 60);
        QCOMPARE(model().rowCount(), 100);
        QCOMPARE(model().droppedCount(), 150);
        QCOMPARE(model().receivedCount(), 250);
        QCOMPARE(model().entry(0).record.msecsSinceEpoch, 150);
        QCOMPARE(model().entry(99).record.msecsSinceEpoch, 249);
        const QString status = m_monitor->statusText();
        QVERIFY2(status.contains(QStringLiteral("150 older telegram")), qPrintable(status));
        QVERIFY2(status.contains(QStringLiteral("latest 100")), qPrintable(status));
    }

    void aFastStreamIsShownInBatches()
    {
        QSignalSpy inserted(&model(), &QAbstractItemModel::rowsInserted);
        for (int i = 0; i < 30000; ++i)
            model().append(record(TrafficRecord::Kind::Sent, i, "ab", QStringLiteral("fast")));
        QCOMPARE(model().rowCount(), 0); // nothing drawn per record
        QTRY_COMPARE(model().rowCount(), TrafficModel::kDefaultCapacity);
        QCOMPARE(inserted.size(), 1);
        QCOMPARE(model().droppedCount(), 30000 - TrafficModel::kDefaultCapacity);
    }

    void followsTheNewestUnlessScrolledUp()
    {
        m_monitor->resize(700, 300);
        m_monitor->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_monitor.get()));
        QScrollBar *bar = m_monitor->view()->verticalScrollBar();
        feed(500);
        QTRY_VERIFY(bar->maximum() > 0);
        QCOMPARE(bar->value(), bar->maximum());
        const int before = bar->maximum();
        feed(100, 500);
        QCOMPARE(bar->maximum(), before + 100);
        QCOMPARE(bar->value(), bar->maximum());

        // Scrolled up: the rows in view stay, even when the oldest are dropped.
        bar->setValue(200);
        const auto topTimestamp = [this] {
            return m_monitor->view()
                ->indexAt(QPoint(2, 2))
                .data(TrafficModel::TimestampRole)
                .toLongLong();
        };
        QTRY_COMPARE(topTimestamp(), 200);
        feed(50, 600);
        QTRY_VERIFY(bar->maximum() > 200);
        QCOMPARE(topTimestamp(), 200);
        model().setCapacity(650);
        feed(30, 650);
        QCOMPARE(model().droppedCount(), 30);
        QTRY_COMPARE(topTimestamp(), 200);
        QVERIFY(bar->value() < bar->maximum());

        // Back at the bottom, it follows again.
        bar->setValue(bar->maximum());
        feed(10, 680);
        QTRY_COMPARE(bar->value(), bar->maximum());
        QTreeView *view = m_monitor->view();
        const QModelIndex newest = view->model()->index(view->model()->rowCount() - 1, 0);
        QCOMPARE(newest.data(TrafficModel::TimestampRole).toLongLong(), 689);
        QVERIFY(view->viewport()->rect().contains(view->visualRect(newest)));
    }

    // Each answer reads as the answer to its request: the parameter by id and name, the value
    // as the drive shows it, the sets as a list. Before a scan, the id comes from the address.
    void answersReadAsTheAnswersToTheirRequests_data()
    {
        QTest::addColumn<QString>("protocol");
        QTest::newRow("hsp5") << QStringLiteral("hsp5");
        QTest::newRow("din66019ii") << QStringLiteral("din66019ii");
    }
    void answersReadAsTheAnswersToTheirRequests()
    {
        QFETCH(QString, protocol);
        DriveClient client(simulated(*protocolFromName(protocol)), everyLink());
        m_monitor->attach(&client);
        QVERIFY(connectClient(client));
        const QAbstractItemModel &shown = *m_monitor->filterModel();

        // No description yet: ids from the address, raw values, never a made-up 0000h.
        QVERIFY(finished(client.readValueStandard(kActualLoad, 0)));
        QTRY_COMPARE(meaningsOf(shown, QStringLiteral("← drive")).size(), 1);
        QStringList answers = meaningsOf(shown, QStringLiteral("← drive"));
        QVERIFY2(answers.first().startsWith(QStringLiteral("020Dh: ")), qPrintable(answers.first()));
        QStringList requests = meaningsOf(shown, QStringLiteral("→ drive"));
        QCOMPARE(requests.size(), 1);
        // DIN66019II: "to drive 1: " first where the request selects the drive.
        QVERIFY2(requests.first().endsWith(QStringLiteral("read 020Dh")), qPrintable(requests.first()));

        const auto loadAnswers = [&] {
            const QStringList answers = meaningsOf(shown, QStringLiteral("← drive"));
            return std::count_if(answers.cbegin(), answers.cend(), [](const QString &answer) {
                return answer.startsWith(QStringLiteral("020Dh: "));
            });
        };
        const qsizetype loadAnswersBefore = loadAnswers();

        ScanOptions options;
        options.groupPages = { 0x02, 0x03 }; // ru, op
        options.values = false;
        QFuture<DriveDescription> scan = client.scan(options);
        QVERIFY(QTest::qWaitFor([&] { return scan.isFinished(); }, kWaitMs));
        const DriveDescription drive = scan.result();
        QVERIFY(drive.find(kActualLoad));
        // The scan's records may still be on their way to this thread. The client reports in
        // order: once the answer to a read sent after the scan is shown, all of them are in.
        // (The read before the scan ended in the same words: a new such answer is this one's.)
        QVERIFY(finished(client.readValueStandard(kActualLoad, 0)));
        QTRY_VERIFY(loadAnswers() > loadAnswersBefore);
        QVERIFY(meaningsOf(shown, QStringLiteral("← drive")).constLast().startsWith(
            QStringLiteral("020Dh: ")));
        m_monitor->clear();
        m_monitor->setDrive(std::make_shared<const DriveDescription>(drive));

        const QFuture<Reply> load = client.readValueStandard(kActualLoad, 0);
        QVERIFY(finished(load));
        const Reply reply = load.result();
        QVERIFY(reply.response.as<ParameterValue>());
        const qint32 raw = reply.response.as<ParameterValue>()->value;
        // On a loaded machine a try may time out and be asked again: the rows of this read are
        // there, whatever else the line saw.
        const QString expected = QStringLiteral("ru.13 Actual load: %1 %").arg(raw);
        QTRY_VERIFY(meaningsOf(shown, QStringLiteral("← drive")).contains(expected));
        answers = meaningsOf(shown, QStringLiteral("← drive"));
        requests = meaningsOf(shown, QStringLiteral("→ drive"));
        QVERIFY(!requests.isEmpty());
        QStringList everything;
        for (int row = 0; row < shown.rowCount(); ++row) {
            everything << cell(shown, row, TrafficModel::DirectionColumn) + QLatin1Char(' ')
                              + cell(shown, row, TrafficModel::MeaningColumn);
        }
        for (const QString &request : std::as_const(requests)) {
            QVERIFY2(request.endsWith(QStringLiteral("read ru.13 Actual load")),
                     qPrintable(everything.join(QLatin1Char('\n'))));
        }
        for (const QString &answer : std::as_const(answers))
            QVERIFY2(!answer.contains(QStringLiteral("020Dh")), qPrintable(answer));

        // A write to set 0 is set 0 (mask 01h), its answer the value written; sets as a list.
        m_monitor->clear();
        QVERIFY(finished(client.writeValue(kMaxSpeedForward, 1500, 0x01)));
        QVERIFY(finished(client.readValue(kMaxSpeedForward, 0x24)));
        QTRY_COMPARE(meaningsOf(shown, QStringLiteral("← drive")).size(), 2);
        requests = meaningsOf(shown, QStringLiteral("→ drive"));
        answers = meaningsOf(shown, QStringLiteral("← drive"));
        QCOMPARE(requests.size(), 2);
        QVERIFY2(requests[0].contains(QStringLiteral("write op.11 "))
                     && requests[0].endsWith(QStringLiteral(" (set 0)")),
                 qPrintable(requests[0]));
        QVERIFY2(answers[0].startsWith(QStringLiteral("written: op.11 "))
                     && answers[0].endsWith(QStringLiteral(" (set 0)")),
                 qPrintable(answers[0]));
        QVERIFY2(requests[1].endsWith(QStringLiteral(" (sets 2, 5)")), qPrintable(requests[1]));
        QVERIFY2(answers[1].startsWith(QStringLiteral("op.11 "))
                     && answers[1].endsWith(QStringLiteral(" (sets 2, 5)")),
                 qPrintable(answers[1]));
        QVERIFY(rowsOf(shown, QStringLiteral("error")).isEmpty());

        // The filter finds what the rows say.
        m_monitor->setFilterText(QStringLiteral("actual load"));
        QCOMPARE(shown.rowCount(), 0);
        m_monitor->setFilterText(QStringLiteral("op.11"));
        QCOMPARE(shown.rowCount(), 4);

        // A parameter file opened (the session closed) or another drive scanned: the telegrams
        // captured before keep the names of their time, those captured from now on have none.
        m_monitor->setFilterText({});
        const QStringList before = meaningsOf(shown, QStringLiteral("← drive"));
        m_monitor->setDrive(nullptr);
        QCOMPARE(meaningsOf(shown, QStringLiteral("← drive")), before);
        for (const QString &answer : before)
            QVERIFY2(!answer.contains(QStringLiteral("030Bh")), qPrintable(answer));
        QVERIFY(finished(client.readValue(kMaxSpeedForward, 0x01)));
        QTRY_COMPARE(meaningsOf(shown, QStringLiteral("← drive")).size(), before.size() + 1);
        QVERIFY2(meaningsOf(shown, QStringLiteral("← drive")).constLast().startsWith(
                     QStringLiteral("030Bh")),
                 qPrintable(meaningsOf(shown, QStringLiteral("← drive")).constLast()));
        QCOMPARE(meaningsOf(shown, QStringLiteral("← drive")).mid(0, before.size()), before);
    }

    // A drive that stops answering: every attempt that timed out is an error row, naming the
    // request it was, so "Errors only" shows them.
    void aRequestWithoutAnswerShowsUnderErrorsOnly_data()
    {
        QTest::addColumn<QString>("protocol");
        QTest::newRow("hsp5") << QStringLiteral("hsp5");
        QTest::newRow("din66019ii") << QStringLiteral("din66019ii");
    }
    void aRequestWithoutAnswerShowsUnderErrorsOnly()
    {
        QFETCH(QString, protocol);
        SimulationOptions silent;
        silent.dropByteRate = 1.0;
        ClientOptions options;
        options.timeoutMs = 20;
        options.retries = 1;
        DriveClient client(simulated(*protocolFromName(protocol), silent), everyLink(), options);
        m_monitor->attach(&client);
        QVERIFY(connectClient(client));
        const QFuture<Reply> read = client.readValue(kMaxSpeedForward, 0x01);
        QVERIFY(finished(read));
        QCOMPARE(read.result().status, Reply::Status::Timeout);
        QTRY_COMPARE(model().receivedCount(), model().rowCount());
        QTest::qWait(2 * TrafficModel::kBatchIntervalMs); // the last records on their way
        model().flush();

        m_monitor->setErrorsOnly(true);
        const QAbstractItemModel &shown = *m_monitor->filterModel();
        QStringList timeouts;
        for (const QString &meaning : meaningsOf(shown, QStringLiteral("error"))) {
            if (meaning.contains(QStringLiteral("no answer")))
                timeouts << meaning;
        }
        QCOMPARE(timeouts.size(), 2);
        QVERIFY2(timeouts[0].contains(QStringLiteral("attempt 1 of 2"))
                     && timeouts[0].contains(QStringLiteral("asking again"))
                     && timeouts[0].endsWith(QStringLiteral("read 030Bh (set 0)")),
                 qPrintable(timeouts[0]));
        QVERIFY2(timeouts[1].contains(QStringLiteral("attempt 2 of 2"))
                     && timeouts[1].contains(QStringLiteral("given up")),
                 qPrintable(timeouts[1]));
    }

    // Every text of the meaning column goes through tr(): requests, answers, sets, timeouts.
    void theMeaningsAreTranslatable()
    {
        MarkingTranslator marking;
        QVERIFY(QCoreApplication::installTranslator(&marking));
        const auto restore = qScopeGuard([&] { QCoreApplication::removeTranslator(&marking); });
        SimulationOptions silent;
        silent.dropByteRate = 1.0;
        ClientOptions options;
        options.timeoutMs = 20;
        options.retries = 0;
        DriveClient client(simulated(Protocol::Hsp5), everyLink());
        DriveClient silentClient(simulated(Protocol::Hsp5, silent), everyLink(), options);
        QVERIFY(connectClient(client));
        QVERIFY(connectClient(silentClient));
        m_monitor->attach(&client);
        QVERIFY(finished(client.writeValue(kMaxSpeedForward, 1500, 0x01)));
        QTRY_COMPARE(model().rowCount(), 2);
        m_monitor->attach(&silentClient);
        QVERIFY(finished(silentClient.readValueStandard(kActualLoad, 0)));
        QTest::qWait(2 * TrafficModel::kBatchIntervalMs); // the last records on their way
        model().flush();

        const QAbstractItemModel &shown = *m_monitor->filterModel();
        QStringList meanings = meaningsOf(shown, TrafficFormat::direction(TrafficRecord::Kind::Sent))
            + meaningsOf(shown, TrafficFormat::direction(TrafficRecord::Kind::Received))
            + meaningsOf(shown, TrafficFormat::direction(TrafficRecord::Kind::Error));
        QVERIFY(meanings.size() >= 4);
        for (const QString &meaning : std::as_const(meanings))
            QVERIFY2(meaning.startsWith(MarkingTranslator::kMark), qPrintable(meaning));
        QVERIFY2(meanings[0].endsWith(MarkingTranslator::kMark + QStringLiteral("set 0)")),
                 qPrintable(meanings[0]));
    }

    // Opened while telegrams stream in, the list follows the newest; scrolled up, it stays.
    void openedWhileTelegramsArriveItFollowsTheNewest()
    {
        feed(300); // the dock is closed
        m_monitor->resize(700, 300);
        m_monitor->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_monitor.get()));
        QScrollBar *bar = m_monitor->view()->verticalScrollBar();
        QTRY_VERIFY(bar->maximum() > 0);
        QTRY_COMPARE(bar->value(), bar->maximum());
        feed(50, 300);
        QTRY_COMPARE(bar->value(), bar->maximum());
        QTreeView *view = m_monitor->view();
        const QModelIndex newest = view->model()->index(view->model()->rowCount() - 1, 0);
        QVERIFY(view->viewport()->rect().contains(view->visualRect(newest)));

        // Closed and opened again after more arrived: still the newest.
        m_monitor->hide();
        feed(100, 350);
        m_monitor->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_monitor.get()));
        QTRY_COMPARE(bar->value(), bar->maximum());
        feed(10, 450);
        QTRY_COMPARE(bar->value(), bar->maximum());

        // Scrolled up by the user, it stays where it is.
        bar->triggerAction(QAbstractSlider::SliderPageStepSub);
        const int kept = bar->value();
        QVERIFY(kept < bar->maximum());
        const int maximumBefore = bar->maximum();
        feed(10, 460);
        // The new rows have been laid out (the range grew): a list that followed them would
        // have moved by now.
        QTRY_VERIFY(bar->maximum() > maximumBefore);
        QCOMPARE(bar->value(), kept);
    }

    void saveWritesTheRowsShown()
    {
        model().append(record(TrafficRecord::Kind::Sent, 1000, QByteArray::fromHex("0102"),
                              QStringLiteral("read 030Bh, set \"1\"")));
        model().setProtocol(Protocol::Din66019II);
        model().append(record(TrafficRecord::Kind::Received, 2000, QByteArray("\x02G1\x03", 4),
                              QStringLiteral("answer")));
        model().append(record(TrafficRecord::Kind::Error, 3000, {}, QStringLiteral("timeout")));
        model().flush();

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString csvPath = dir.filePath(QStringLiteral("telegrams.csv"));
        QString error;
        QVERIFY2(m_monitor->saveTo(csvPath, &error), qPrintable(error));
        QVERIFY(m_monitor->noticeText().contains(QStringLiteral("3 telegram")));
        QFile csv(csvPath);
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList csvLines
            = QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(csvLines.size(), 4);
        QCOMPARE(csvLines[0], QStringLiteral("Time,Direction,Bytes,Characters,Meaning"));
        QVERIFY2(
            csvLines[1].endsWith(QStringLiteral(",→ drive,01 02,,\"read 030Bh, set \"\"1\"\"\"")),
            qPrintable(csvLines[1]));
        QVERIFY2(csvLines[2].endsWith(QStringLiteral(",← drive,02 47 31 03,<STX>G1<ETX>,answer")),
                 qPrintable(csvLines[2]));
        QVERIFY(csvLines[3].endsWith(QStringLiteral(",error,,,timeout")));
        QVERIFY(csvLines[1].contains(
            QRegularExpression(QStringLiteral("^\\d{4}-\\d\\d-\\d\\d \\d\\d:"))));

        m_monitor->setErrorsOnly(true);
        const QString textPath = dir.filePath(QStringLiteral("errors.txt"));
        QVERIFY(m_monitor->saveTo(textPath));
        QFile text(textPath);
        QVERIFY(text.open(QIODevice::ReadOnly));
        const QStringList textLines
            = QString::fromUtf8(text.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(textLines.size(), 2);
        QVERIFY(textLines[1].endsWith(QStringLiteral("\terror\t\t\ttimeout")));
    }

    void aFailedSaveSaysWhyAndLeavesNothing()
    {
        feed(3);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("missing/telegrams.csv"));
        QString error;
        QVERIFY(!m_monitor->saveTo(path, &error));
        QVERIFY2(error.contains(QDir::toNativeSeparators(path)), qPrintable(error));
        QCOMPARE(m_monitor->noticeText(), error);
        QVERIFY(QDir(dir.path())
                    .entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden)
                    .isEmpty());
        QCOMPARE(model().rowCount(), 3);
    }

    void ctrlCCopiesTheSelectedRows()
    {
        feed(5);
        m_monitor->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_monitor.get()));
        QTreeView *view = m_monitor->view();
        view->setFocus();
        auto *selection = view->selectionModel();
        selection->select(view->model()->index(3, 0),
                          QItemSelectionModel::Select | QItemSelectionModel::Rows);
        selection->select(view->model()->index(1, 0),
                          QItemSelectionModel::Select | QItemSelectionModel::Rows);
        QApplication::clipboard()->clear();
        QTest::keySequence(view, QKeySequence::Copy);
        const QStringList lines
            = QApplication::clipboard()->text().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 2);
        QVERIFY2(lines[0].endsWith(QStringLiteral("\t→ drive\t31\ttelegram 1")),
                 qPrintable(lines[0]));
        QVERIFY(lines[1].endsWith(QStringLiteral("\t→ drive\t33\ttelegram 3")));
    }

    void theApplicationIconIsAResource()
    {
        QVERIFY(QFile::exists(QStringLiteral(":/icons/drivedesk.svg")));
        for (int size : { 16, 32, 48, 64, 128, 256 }) {
            const QIcon icon(QStringLiteral(":/icons/drivedesk-%1.png").arg(size));
            QVERIFY2(!icon.isNull(), qPrintable(QString::number(size)));
            QCOMPARE(icon.availableSizes().value(0), QSize(size, size));
        }
    }
};

QTEST_MAIN(TestTelegramMonitor)
#include "tst_telegrammonitor.moc"
