#include "tst_mainwindow_support.h"

#include "edit/PollingController.h"
#include "frame/DriveSession.h"
#include "frame/NoticeBar.h"
#include "main/RecentConnections.h"
#include "parameters/ParameterProperties.h"
#include "protocol/hsp5/Hsp5Codec.h"
#include "protocol/hsp5/Hsp5Layout.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QCheckBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>

#include <memory>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

// The main window against the simulated F5: connecting and scanning, browsing groups, search
// and filters, favourites, a lost link and reconnecting, cancelling a scan.
class TestMainWindow : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    std::unique_ptr<MainWindow> m_window;

    QString statusLabel(const char *name) const
    {
        const auto *label = m_window->statusBar()->findChild<QLabel *>(QString::fromLatin1(name));
        return label ? label->text() : QString();
    }

    void clickGroup(const QString &text)
    {
        QTreeView *tree = m_window->browser()->groupTree();
        const QModelIndex item = groupItem(*m_window, text);
        QVERIFY2(item.isValid(), qPrintable(text));
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, tree->visualRect(item).center());
    }

    // The groups without their values: live values change from one read to the next.
    static QList<GroupDescription> metadataOf(DriveDescription drive)
    {
        for (GroupDescription &group : drive.groups) {
            for (ParameterDescription &parameter : group.parameters) {
                parameter.values = {};
                parameter.error.clear();
            }
        }
        return drive.groups;
    }

    QString rootText() const { return m_window->browser()->view()->rootIndex().data().toString(); }

private slots:
    void init()
    {
        m_settings.clear();
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1300, 800);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    }

    void cleanup() { m_window.reset(); }

    void connectingScansTheDriveIntoTheWindow()
    {
        const auto *polling = m_window->findChild<QAction *>(QStringLiteral("pollingAction"));
        QVERIFY(polling && !polling->isEnabled());
        m_window->connectTo(simulated());
        QVERIFY(m_window->noticeBar()->isVisible());
        QCOMPARE(m_window->noticeBar()->kind(), NoticeBar::Kind::Progress);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->isReady(), kWaitMs);
        QVERIFY(!m_window->noticeBar()->isVisible());

        const QAbstractItemModel *groups = m_window->browser()->groupTree()->model();
        const auto text = [groups](int row, int column) {
            return groups->index(row, column).data().toString();
        };
        QCOMPARE(groups->rowCount(), kSimulatedGroups + 1);
        QCOMPARE(text(0, 0), QStringLiteral("All parameters"));
        QCOMPARE(text(0, 1), QString::number(kSimulatedParameters));
        QStringList ids;
        for (int row = 1; row < groups->rowCount(); ++row)
            ids << text(row, 0).section(QStringLiteral("  "), 0, 0);
        QCOMPARE(ids.mid(0, 5),
                 (QStringList { QStringLiteral("ru"), QStringLiteral("op"), QStringLiteral("Pn"),
                                QStringLiteral("uF"), QStringLiteral("dr") }));
        QCOMPARE(text(1, 0), QStringLiteral("ru  Run parameters"));
        QCOMPARE(text(1, 1), QStringLiteral("18"));
        QCOMPARE(shownAddresses(*m_window).size(), kSimulatedParameters);
        QVERIFY(m_window->model()->state()->value(kInverterState, 0).has_value());
        QVERIFY(polling->isEnabled());

        QTRY_COMPARE(statusLabel("passwordLevel"), QStringLiteral("Password level: Application"));
        QTRY_VERIFY(statusLabel("parameterSets").contains(QStringLiteral("Active set: 0")));
        QVERIFY(statusLabel("parameterSets").contains(QStringLiteral("Set pointer (Fr.09): 0")));
        QVERIFY(statusLabel("connectionState").startsWith(QStringLiteral("Connected")));
        // Named by its identification parameters: HSP5 has no identification service.
        QVERIFY2(m_window->windowTitle().contains(QStringLiteral("software 1.82, serial number")),
                 qPrintable(m_window->windowTitle()));
        QCOMPARE(RecentConnections::last().kind, ConnectionSettings::Kind::Simulated);
    }

    void groupsChooseWhatTheTableShows()
    {
        QVERIFY(connectAndRead(*m_window, simulated()));
        ParameterView *view = m_window->browser()->view();

        clickGroup(QStringLiteral("op  "));
        QCOMPARE(rootText(), QStringLiteral("op  Operational parameters"));
        const QList<quint16> op = shownAddresses(*m_window);
        QCOMPARE(op.size(), 17);
        for (quint16 address : op)
            QCOMPARE(address & 0xFF00, 0x0300);
        QVERIFY(!view->isColumnHidden(ParameterModel::FirstSetColumn + 7));

        // The run display has no set-programmable parameter: one value column.
        clickGroup(QStringLiteral("ru  "));
        QCOMPARE(rootText(), QStringLiteral("ru  Run parameters"));
        QCOMPARE(shownAddresses(*m_window).size(), 18);
        QCOMPARE(view->model()->index(0, 0, view->rootIndex()).data().toString(),
                 QStringLiteral("ru.00"));
        QVERIFY(view->isColumnHidden(ParameterModel::FirstSetColumn + 1));
        QVERIFY(!view->isColumnHidden(ParameterModel::FirstSetColumn));

        clickGroup(QStringLiteral("All parameters"));
        QVERIFY(!view->rootIndex().isValid());
        QCOMPARE(shownAddresses(*m_window).size(), kSimulatedParameters);
        QCOMPARE(m_window->browser()->shownGroup(), QString());
    }

    // The group list is the parameter model's own group rows, kept whole through a rescan, and
    // can be walked with the keyboard.
    void groupListFollowsTheModelAndTheKeyboard()
    {
        QTreeView *tree = m_window->browser()->groupTree();
        QAbstractItemModelTester tester(tree->model(),
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(tree->model()->rowCount(), 1); // "All parameters" before any drive
        QVERIFY(connectAndRead(*m_window, simulated()));
        QCOMPARE(tree->model()->rowCount(), kSimulatedGroups + 1);

        tree->setFocus();
        tree->setCurrentIndex(groupItem(*m_window, QStringLiteral("All parameters")));
        QTest::keyClick(tree, Qt::Key_Down);
        QCOMPARE(m_window->browser()->shownGroup(), QStringLiteral("ru"));
        QCOMPARE(rootText(), QStringLiteral("ru  Run parameters"));
        QTest::keyClick(tree, Qt::Key_Down);
        QCOMPARE(m_window->browser()->shownGroup(), QStringLiteral("op"));
        QCOMPARE(tree->currentIndex().data().toString(),
                 QStringLiteral("op  Operational parameters"));
        QCOMPARE(tree->currentIndex().siblingAtColumn(1).data().toString(), QStringLiteral("17"));

        // Reading the drive again keeps the group chosen, in the list and in the table.
        QSignalSpy reset(m_window->model(), &QAbstractItemModel::modelReset);
        QVERIFY(connectAndRead(*m_window, simulated()));
        QVERIFY(!reset.isEmpty());
        QCOMPARE(tree->currentIndex().data().toString(),
                 QStringLiteral("op  Operational parameters"));
        QCOMPARE(m_window->browser()->shownGroup(), QStringLiteral("op"));
        QCOMPARE(rootText(), QStringLiteral("op  Operational parameters"));
        QTest::keyClick(tree, Qt::Key_Home);
        QCOMPARE(m_window->browser()->shownGroup(), QString());
        QVERIFY(!m_window->browser()->view()->rootIndex().isValid());
    }

    void searchAsYouTypeLooksThroughEveryGroup()
    {
        QVERIFY(connectAndRead(*m_window, simulated()));
        clickGroup(QStringLiteral("op  "));
        QLineEdit *search = m_window->browser()->searchField();
        QTest::keySequence(m_window.get(), QKeySequence::Find);
        QTRY_VERIFY(search->hasFocus());

        QTest::keyClicks(search, QStringLiteral("speed"));
        const QList<quint16> found = shownAddresses(*m_window);
        QVERIFY(found.size() > 3);
        QVERIFY(found.size() < kSimulatedParameters);
        QSet<int> pages;
        for (quint16 address : found) {
            const QModelIndex index = m_window->model()->indexOf(address);
            QVERIFY(index.data(ParameterModel::SearchTextRole)
                        .toString()
                        .contains(QStringLiteral("speed")));
            pages.insert(address >> 8);
        }
        QVERIFY2(pages.size() > 1, "a search looks through every group, not just op");
        QVERIFY(m_window->browser()
                    ->findChild<QLabel *>(QStringLiteral("scopeLabel"))
                    ->text()
                    .startsWith(QStringLiteral("Search results")));

        search->clear();
        QTest::keyClicks(search, QStringLiteral("ru.3"));
        QVERIFY(shownAddresses(*m_window).contains(quint16(0x0203)));

        // Nothing matches: the table says so instead of showing an empty grid.
        search->clear();
        QTest::keyClicks(search, QStringLiteral("no such parameter"));
        QVERIFY(shownAddresses(*m_window).isEmpty());
        QVERIFY(
            m_window->browser()->findChild<QLabel *>(QStringLiteral("emptyNotice"))->isVisible());

        search->clear();
        QCOMPARE(rootText(), QStringLiteral("op  Operational parameters"));
        QCOMPARE(shownAddresses(*m_window).size(), 17);
    }

    void differsFromDefaultShowsWhatWasChanged()
    {
        QVERIFY(connectAndRead(*m_window, simulated()));
        int differing = 0;
        ParameterModel *model = m_window->model();
        for (int group = 0; group < model->rowCount(); ++group) {
            for (int row = 0; row < model->rowCount(model->index(group, 0)); ++row) {
                differing += model->index(row, 0, model->index(group, 0))
                                 .data(ParameterModel::DiffersFromDefaultRole)
                                 .toBool();
            }
        }
        QVERIFY(differing > 0);

        auto *box = m_window->browser()->findChild<QCheckBox *>();
        QVERIFY(box);
        QCOMPARE(box->text().remove(QLatin1Char('&')), QStringLiteral("Differs from default"));
        box->click();
        QVERIFY(m_window->browser()->differsAction()->isChecked());
        const QList<quint16> shown = shownAddresses(*m_window);
        QCOMPARE(shown.size(), differing);
        for (quint16 address : shown) {
            QVERIFY(model->indexOf(address).data(ParameterModel::DiffersFromDefaultRole).toBool());
            // Only what the user sets: no read-only value, nothing the drive changes itself.
            const ParameterDescription *parameter = model->state()->parameter(address);
            const ParameterProperties properties(parameter->properties1, parameter->properties2);
            QVERIFY2(!properties.isReadOnly() && !properties.isChangedByInverter(),
                     qPrintable(model->indexOf(address).data().toString()));
        }
        QVERIFY(!shown.contains(0x0212)); // ru.18 DC link voltage
        QVERIFY(!shown.contains(0x0E0A)); // In.10 serial number
        m_window->browser()->differsAction()->trigger();
        QVERIFY(!box->isChecked());
        QCOMPARE(shownAddresses(*m_window).size(), kSimulatedParameters);
    }

    void favouritesAreStarredAndRememberedPerDrive()
    {
        QVERIFY(connectAndRead(*m_window, simulated()));
        m_window->browser()->showGroup(QStringLiteral("op"));
        ParameterView *view = m_window->browser()->view();
        const QModelIndex id
            = viewIndex(*m_window, kFixedSpeed1).siblingAtColumn(ParameterModel::IdColumn);
        view->scrollTo(id);
        const QRect star = view->starRect(id);
        QVERIFY(!star.isEmpty());
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, star.center());
        QVERIFY(m_window->model()->isFavourite(kFixedSpeed1));

        m_window->browser()->showGroup(QString());
        m_window->browser()->favouritesAction()->trigger();
        QCOMPARE(shownAddresses(*m_window), QList<quint16> { kFixedSpeed1 });

        // Another window on the same drive finds the star again.
        MainWindow second;
        QVERIFY(connectAndRead(second, simulated()));
        QVERIFY(second.model()->isFavourite(kFixedSpeed1));
        QCOMPARE(second.model()->favourites().size(), 1);
    }

    void theWindowSendsOnlyWhatTheDriveCanFrame()
    {
        // The simulated drive knows exactly seed 000's services over HSP5, as a real one does.
        m_window->connectTo(simulated());
        QVERIFY(m_window->session());
        QSignalSpy traffic(m_window->session()->client(), &DriveClient::traffic);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->isReady(), kWaitMs);
        auto *polling = m_window->findChild<QAction *>(QStringLiteral("pollingAction"));
        QVERIFY(polling);
        if (!polling->isChecked())
            polling->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(traffic.size() > 1000, kWaitMs);
        // Polling's requests are in the traffic too once a few of its rounds came back.
        const PollingController *rounds = m_window->findChild<PollingController *>();
        QTRY_VERIFY_WITH_TIMEOUT(rounds->roundsCompleted() >= 3, kWaitMs);

        const auto decoder
            = Hsp5Codec(Hsp5Services::WithExtensions).makeDecoder(Role::Drive);
        int requests = 0;
        for (const QList<QVariant> &arguments : std::as_const(traffic)) {
            const auto record = arguments.at(0).value<TrafficRecord>();
            QVERIFY2(record.kind != TrafficRecord::Kind::Error, qPrintable(record.meaning));
            if (record.kind != TrafficRecord::Kind::Sent)
                continue;
            decoder->feed(record.bytes);
            while (const std::optional<Decoded> item = decoder->next()) {
                const auto *telegram = std::get_if<Telegram>(&*item);
                QVERIFY(telegram);
                ++requests;
                const Access access = telegram->access;
                QVERIFY2(hsp5Layout(telegram->service, access, Direction::Request),
                         qPrintable(describe(*telegram)));
            }
        }
        QVERIFY(requests > 1000);
        QVERIFY(!m_window->noticeBar()->isVisible()
                || m_window->noticeBar()->kind() != NoticeBar::Kind::Problem);
    }

    void theNextConnectionTakesTheMetadataFromTheCache()
    {
        QVERIFY(connectAndRead(*m_window, simulated()));
        const auto *fromCache
            = m_window->statusBar()->findChild<QLabel *>(QStringLiteral("metadataSource"));
        QVERIFY(fromCache);
        QVERIFY(!fromCache->isVisible());
        const DriveDescription cold = m_window->model()->state()->description();
        QVERIFY(!cold.metadataFromCache);

        MainWindow second;
        second.show();
        QVERIFY(connectAndRead(second, simulated()));
        const DriveDescription warm = second.model()->state()->description();
        QVERIFY(warm.metadataFromCache);
        QCOMPARE(metadataOf(warm), metadataOf(cold));
        const auto *secondLabel
            = second.statusBar()->findChild<QLabel *>(QStringLiteral("metadataSource"));
        QVERIFY(secondLabel->isVisible());
        QCOMPARE(secondLabel->text(), QStringLiteral("Metadata from cache"));
        // A long message stops at the field's frame instead of running into its text: every
        // permanent field of the bar stands in a frame of its own.
        second.statusBar()->showMessage(QString(300, QLatin1Char('x')));
        for (const QLabel *field : second.statusBar()->findChildren<QLabel *>(
                 QString(), Qt::FindDirectChildrenOnly)) {
            if (!field->objectName().isEmpty())
                QVERIFY2(field->frameShape() != QFrame::NoFrame, qPrintable(field->objectName()));
        }

        // Drive > Read Metadata Again: everything from the drive.
        auto *again = second.findChild<QAction *>(QStringLiteral("readMetadataAction"));
        QVERIFY(again && again->isEnabled());
        again->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!second.model()->state()->description().metadataFromCache, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(second.isReady(), kWaitMs);
        QVERIFY(!secondLabel->isVisible());
        QCOMPARE(metadataOf(second.model()->state()->description()), metadataOf(cold));
    }

    void lostLinkKeepsWhatWasReadAndReconnects()
    {
        ServedDrive server(Protocol::Hsp5, answeringAtOnce());
        const QString problem = serveAndConnect(*m_window, server);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        const std::optional<qint32> before = m_window->model()->state()->value(kDemoPeriod, 0);
        QVERIFY(before);

        server.close();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->noticeBar()->kind(), NoticeBar::Kind::Problem, kWaitMs);
        QVERIFY(m_window->noticeBar()->isVisible());
        QVERIFY(m_window->noticeBar()->text().contains(QStringLiteral("lost")));
        QCOMPARE(statusLabel("connectionState"), QStringLiteral("Connection lost"));
        QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("lost")));
        // What was read stays; nothing can be edited meanwhile.
        QCOMPARE(m_window->model()->rowCount(), kSimulatedGroups);
        QCOMPARE(m_window->model()->state()->value(kDemoPeriod, 0), before);
        QCOMPARE(m_window->browser()->view()->editTriggers(), QAbstractItemView::NoEditTriggers);
        QVERIFY(!m_window->isReady());
        QVERIFY(!m_window->findChild<QAction *>(QStringLiteral("pollingAction"))->isEnabled());

        QString error;
        QVERIFY2(server.listen(server.port(), &error), qPrintable(error));
        auto *reconnect
            = m_window->noticeBar()->findChild<QPushButton *>(QStringLiteral("noticeReconnect"));
        QVERIFY(reconnect && reconnect->isVisible());
        QTest::mouseClick(reconnect, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->isReady(), kWaitMs);
        QVERIFY(!m_window->noticeBar()->isVisible());
        QVERIFY(m_window->browser()->view()->editTriggers() != QAbstractItemView::NoEditTriggers);
        QCOMPARE(m_window->model()->rowCount(), kSimulatedGroups);
    }

    void aDriveThatStopsAnsweringIsShownAsSuchAndRecovers()
    {
        ServedDrive server(Protocol::Hsp5, answeringAtOnce());
        const QString problem = serveAndConnect(*m_window, server);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        auto *polling = m_window->findChild<QAction *>(QStringLiteral("pollingAction"));
        polling->setChecked(true);
        PollingController *controller = m_window->findChild<PollingController *>();
        QTRY_VERIFY_WITH_TIMEOUT(controller->roundsCompleted() > 0, kWaitMs);
        const QModelIndex live = m_window->model()->valueIndex(kInverterState, 0);
        QVERIFY(!live.data(ParameterModel::StaleRole).toBool());

        // Frozen behind an open connection: the window says so, without waiting for the user.
        server.setSilent(true);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->noticeBar()->kind(), NoticeBar::Kind::Problem, kWaitMs);
        QVERIFY(m_window->noticeBar()->isVisible());
        QVERIFY2(m_window->noticeBar()->text().contains(QStringLiteral("not answering")),
                 qPrintable(m_window->noticeBar()->text()));
        auto *reconnect
            = m_window->noticeBar()->findChild<QPushButton *>(QStringLiteral("noticeReconnect"));
        QVERIFY(reconnect && reconnect->isVisible());
        QVERIFY2(statusLabel("connectionState").contains(QStringLiteral("not answering")),
                 qPrintable(statusLabel("connectionState")));
        QVERIFY(live.data(ParameterModel::StaleRole).toBool());
        QVERIFY(live.data(ParameterModel::LastReadRole).toDateTime().isValid());
        QVERIFY(live.data(Qt::ToolTipRole).toString().contains(QStringLiteral("not answering")));
        QVERIFY(polling->isChecked());
        const auto pollingSays = [this] {
            return m_window->statusBar()->currentMessage().startsWith(QStringLiteral("Polling:"));
        };
        QTRY_VERIFY_WITH_TIMEOUT(pollingSays(), kWaitMs);

        // It answers again: everything clears by itself.
        server.setSilent(false);
        QTRY_VERIFY_WITH_TIMEOUT(!m_window->noticeBar()->isVisible(), kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(!live.data(ParameterModel::StaleRole).toBool(), kWaitMs);
        QVERIFY(!statusLabel("connectionState").contains(QStringLiteral("not answering")));
        QVERIFY(statusLabel("connectionState").startsWith(QStringLiteral("Connected")));
        QVERIFY(m_window->isReady());
        // What polling said of the frozen drive is no longer so once it reads again.
        QTRY_VERIFY_WITH_TIMEOUT(!pollingSays(), kWaitMs);

        // Nor once polling is switched off while the drive is frozen.
        server.setSilent(true);
        QTRY_VERIFY_WITH_TIMEOUT(pollingSays(), kWaitMs);
        polling->setChecked(false);
        QVERIFY2(!pollingSays(), qPrintable(m_window->statusBar()->currentMessage()));
        server.setSilent(false);
    }

    // Polling off, nobody asking the drive anything: a frozen drive does not go on reading
    // "Connected". The client's check of the idle line finds it (within 5 s, docs/client.md).
    void aFrozenDriveIsShownWithoutPolling()
    {
        ServedDrive server(Protocol::Hsp5, answeringAtOnce());
        const QString problem = serveAndConnect(*m_window, server);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        auto *polling = m_window->findChild<QAction *>(QStringLiteral("pollingAction"));
        QVERIFY(!polling->isChecked());
        QVERIFY(statusLabel("connectionState").startsWith(QStringLiteral("Connected")));

        server.setSilent(true);
        const QString notAnswering = QStringLiteral("not answering");
        QTRY_VERIFY_WITH_TIMEOUT(statusLabel("connectionState").contains(notAnswering), 5000);
        QCOMPARE(m_window->noticeBar()->kind(), NoticeBar::Kind::Problem);
        QVERIFY(m_window->noticeBar()->isVisible());

        // Back: the next check is answered, and the window says so by itself.
        server.setSilent(false);
        QTRY_VERIFY_WITH_TIMEOUT(!statusLabel("connectionState").contains(notAnswering), kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(!m_window->noticeBar()->isVisible(), kWaitMs);
        QVERIFY(m_window->isReady());
    }

    void connectingAgainClosesTheOldLinkFirst()
    {
        // A device server that serves one connection at a time, as the simulator does.
        ServedDrive server(Protocol::Hsp5, answeringAtOnce());
        const QString problem = serveAndConnect(*m_window, server);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        for (int round = 0; round < 4; ++round) {
            QPointer<DriveSession> old = m_window->session();
            m_window->connectTo(server.settings(Protocol::Hsp5));
            QTRY_VERIFY_WITH_TIMEOUT(old.isNull() && m_window->isReady(), kWaitMs);
            QVERIFY2(!m_window->noticeBar()->isVisible()
                         || m_window->noticeBar()->kind() != NoticeBar::Kind::Problem,
                     qPrintable(m_window->noticeBar()->text()));
            QCOMPARE(m_window->model()->rowCount(), kSimulatedGroups);
        }
    }

    void aFailedConnectKeepsWhatWasShown()
    {
        const SimulationOptions options = answeringAtOnce();
        ServedDrive server(Protocol::Hsp5, options);
        const QString problem = serveAndConnect(*m_window, server);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        const std::optional<qint32> before = m_window->model()->state()->value(kDemoPeriod, 0);
        QVERIFY(before);
        const QString title = m_window->windowTitle();

        // A gateway where nothing listens.
        ServedDrive gone(Protocol::Hsp5, options);
        QString error;
        QVERIFY2(gone.listen(0, &error), qPrintable(error));
        const ConnectionSettings nowhere = gone.settings(Protocol::Hsp5);
        gone.close();
        m_window->connectTo(nowhere);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->noticeBar()->kind(), NoticeBar::Kind::Problem, kWaitMs);
        QVERIFY2(m_window->noticeBar()->text().contains(QStringLiteral("Could not connect")),
                 qPrintable(m_window->noticeBar()->text()));
        QCOMPARE(m_window->model()->rowCount(), kSimulatedGroups);
        QCOMPARE(m_window->model()->state()->value(kDemoPeriod, 0), before);
        QCOMPARE(m_window->windowTitle(), title);
        const auto *reconnect
            = m_window->noticeBar()->findChild<QPushButton *>(QStringLiteral("noticeReconnect"));
        const auto *connectButton
            = m_window->noticeBar()->findChild<QPushButton *>(QStringLiteral("noticeConnect"));
        QVERIFY(reconnect->isVisible() && connectButton->isVisible());
        QVERIFY(!m_window->isReady());

        // Back to the first gateway: the drive is read again.
        m_window->connectTo(server.settings(Protocol::Hsp5));
        QTRY_VERIFY_WITH_TIMEOUT(m_window->isReady(), kWaitMs);
        QCOMPARE(m_window->model()->rowCount(), kSimulatedGroups);
    }

    void scanCanBeCancelledAndStartedAgain()
    {
        ConnectionSettings settings = simulated();
        settings.simulation.replyLatencyUs = 3000; // slow enough to cancel halfway
        m_window->connectTo(settings);
        auto *progress
            = m_window->noticeBar()->findChild<QProgressBar *>(QStringLiteral("noticeProgress"));
        // Far enough that parameters have been read.
        QTRY_VERIFY_WITH_TIMEOUT(progress->maximum() == 1000 && progress->value() > 600, 60000);
        auto *cancel
            = m_window->noticeBar()->findChild<QPushButton *>(QStringLiteral("noticeCancel"));
        QTest::mouseClick(cancel, Qt::LeftButton);
        // What was read stays, and is said to be only part of the drive.
        QTRY_COMPARE_WITH_TIMEOUT(m_window->noticeBar()->kind(), NoticeBar::Kind::Problem,
                                  kWaitMs);
        const QString notice = m_window->noticeBar()->text();
        QVERIFY2(notice.contains(QStringLiteral("cancelled"))
                     && notice.contains(QStringLiteral("read only in part")),
                 qPrintable(notice));
        const int shown = m_window->browser()->shownParameterCount();
        QVERIFY2(shown > 0 && shown < kSimulatedParameters, qPrintable(QString::number(shown)));
        QVERIFY2(notice.contains(QStringLiteral("the %1 parameter").arg(shown)),
                 qPrintable(notice));
        QVERIFY(!m_window->statusBar()->currentMessage().startsWith(QStringLiteral("Read ")));
        QVERIFY(m_window->model()->rowCount() > 0);

        // Reading the metadata again reads the whole drive.
        m_window->findChild<QAction *>(QStringLiteral("readMetadataAction"))->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->browser()->shownParameterCount(),
                                  kSimulatedParameters, 60000);
    }

    // A read stopped halfway never passes for the drive: a reconnect after a first scan read in
    // part reads the drive anew, and a re-read stopped halfway leaves the table as it was, its
    // metadata complete, also after a reconnect.
    void stoppedReadsNeverPassForTheDrive()
    {
        ConnectionSettings settings = simulated();
        settings.simulation.replyLatencyUs = 3000; // slow enough to cancel halfway
        m_window->connectTo(settings);
        auto *progress
            = m_window->noticeBar()->findChild<QProgressBar *>(QStringLiteral("noticeProgress"));
        auto *cancel
            = m_window->noticeBar()->findChild<QPushButton *>(QStringLiteral("noticeCancel"));
        auto *reconnect
            = m_window->noticeBar()->findChild<QPushButton *>(QStringLiteral("noticeReconnect"));
        QTRY_VERIFY_WITH_TIMEOUT(progress->maximum() == 1000 && progress->value() > 400, 60000);
        QTest::mouseClick(cancel, Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->noticeBar()->kind(), NoticeBar::Kind::Problem,
                                  kWaitMs);
        QVERIFY(m_window->browser()->shownParameterCount() < kSimulatedParameters);

        // Reconnect: the part read is not refreshed as if it were the drive; the drive is read.
        QVERIFY(reconnect->isVisible());
        QSignalSpy reconnected(m_window->session(), &DriveSession::connected);
        QTest::mouseClick(reconnect, Qt::LeftButton);
        // The notice bar shows the reading until its result is in the table.
        QTRY_VERIFY_WITH_TIMEOUT(reconnected.count() == 1 && m_window->isReady()
                                     && !m_window->noticeBar()->isVisible(),
                                 60000);
        QCOMPARE(m_window->browser()->shownParameterCount(), kSimulatedParameters);
        QVERIFY(m_window->session()->incompleteReason().isEmpty());
        const QList<GroupDescription> complete = metadataOf(m_window->model()->state()->description());
        const auto shownSpeed = [this] {
            return m_window->model()->valueIndex(kFixedSpeed1, 3).data().toString();
        };
        QCOMPARE(shownSpeed(), QStringLiteral("100 1/min"));

        // Read Metadata Again, stopped at about 40 %: the table keeps the complete reading.
        QSignalSpy described(m_window->session(), &DriveSession::described);
        m_window->findChild<QAction *>(QStringLiteral("readMetadataAction"))->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(progress->maximum() == 1000 && progress->value() > 400, 60000);
        QTest::mouseClick(cancel, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->isReady()
                                     && m_window->noticeBar()->kind() != NoticeBar::Kind::Progress,
                                 kWaitMs);
        QCOMPARE(m_window->noticeBar()->kind(), NoticeBar::Kind::Information);
        QVERIFY2(m_window->noticeBar()->text().contains(QStringLiteral("stopped (cancelled)")),
                 qPrintable(m_window->noticeBar()->text()));
        QCOMPARE(described.count(), 0);
        QCOMPARE(m_window->browser()->shownParameterCount(), kSimulatedParameters);
        QCOMPARE(metadataOf(m_window->model()->state()->description()), complete);
        QCOMPARE(shownSpeed(), QStringLiteral("100 1/min"));
        QVERIFY(m_window->model()->state()->isEditable(kFixedSpeed1));

        // And after a reconnect: the values read again into the same complete table.
        QSignalSpy connected(m_window->session(), &DriveSession::connected);
        m_window->session()->reconnect();
        QTRY_VERIFY_WITH_TIMEOUT(connected.count() == 1 && m_window->isReady(), kWaitMs);
        QVERIFY(!m_window->session()->isScanning());
        QCOMPARE(m_window->browser()->shownParameterCount(), kSimulatedParameters);
        QCOMPARE(metadataOf(m_window->model()->state()->description()), complete);
        QCOMPARE(shownSpeed(), QStringLiteral("100 1/min"));
        QVERIFY(m_window->model()->state()->isEditable(kFixedSpeed1));
    }

    void layoutAndFiltersAreRemembered()
    {
        QVERIFY(connectAndRead(*m_window, simulated()));
        m_window->browser()->showGroup(QStringLiteral("uF"));
        m_window->browser()->rawValuesAction()->trigger();
        m_window->browser()->view()->header()->resizeSection(ParameterModel::NameColumn, 321);
        m_window->close();
        m_window.reset();

        MainWindow again;
        QVERIFY(again.browser()->rawValuesAction()->isChecked());
        QVERIFY(connectAndRead(again, simulated()));
        QCOMPARE(again.browser()->shownGroup(), QStringLiteral("uF"));
        QCOMPARE(again.browser()->view()->rootIndex().data().toString().left(4),
                 QStringLiteral("uF  "));
        QCOMPARE(again.browser()->view()->header()->sectionSize(ParameterModel::NameColumn), 321);
        QVERIFY(again.model()->showsRawValues());
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
