#include "tst_mainwindow_support.h"

#include "main/ConnectionDialog.h"
#include "main/DriveInfoDialog.h"
#include "frame/DriveSession.h"
#include "main/FindDrivesDialog.h"
#include "main/RecentConnections.h"
#include "main/StartupOptions.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QToolBar>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabWidget>
#include <QTimer>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

// The shell's dialogs and start-up options: the connection dialog with its checks and recent
// connections, the command line, finding drives on a DIN66019II bus, drive information.
class TestMainWindowDialogs : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;

    template<typename T> static T *child(QWidget &dialog, const char *name)
    {
        auto *found = dialog.findChild<T *>(QString::fromLatin1(name));
        Q_ASSERT(found);
        return found;
    }

private slots:
    void init() { m_settings.clear(); }

    void firstStartOffersTheSimulatedDrive()
    {
        ConnectionDialog dialog;
        QVERIFY(dialog.validate());
        QCOMPARE(dialog.settings().kind, ConnectionSettings::Kind::Simulated);
        QCOMPARE(dialog.settings().protocol, Protocol::Hsp5);
        // HSP5 is point to point: no address to choose, nothing to find.
        QVERIFY(!child<QSpinBox>(dialog, "driveAddress")->isEnabled());
        QVERIFY(!child<QPushButton>(dialog, "findDrives")->isEnabled());
    }

    void emptyEntriesAreRefusedInWords()
    {
        ConnectionDialog dialog;
        auto *tabs = dialog.findChild<QTabWidget *>();
        tabs->setCurrentIndex(1); // TCP
        QString problem;
        QVERIFY(!dialog.validate(&problem));
        QVERIFY2(problem.contains(QStringLiteral("host")), qPrintable(problem));
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Rejected)); // still open
        QCOMPARE(child<QLabel>(dialog, "problem")->text(), problem);

        child<QLineEdit>(dialog, "host")->setText(QStringLiteral("my host"));
        QVERIFY(!dialog.validate(&problem));
        QVERIFY(problem.contains(QStringLiteral("my host")));

        child<QLineEdit>(dialog, "host")->setText(QStringLiteral("10.0.0.7"));
        child<QSpinBox>(dialog, "tcpPort")->setValue(4001);
        QVERIFY(dialog.validate());
        QCOMPARE(dialog.settings().target(), QStringLiteral("tcp:10.0.0.7:4001"));

        tabs->setCurrentIndex(0); // serial
        auto *port = child<QComboBox>(dialog, "serialPort");
        port->setEditText(QString());
        QVERIFY(!dialog.validate(&problem));
        QVERIFY(problem.contains(QStringLiteral("serial port"))
                || problem.contains(QStringLiteral("No serial port")));
        port->setEditText(QStringLiteral("/dev/ttyUSB7"));
        child<QComboBox>(dialog, "baudRate")->setEditText(QStringLiteral("fast"));
        QVERIFY(!dialog.validate(&problem));
        QVERIFY(problem.contains(QStringLiteral("\"fast\" is not a baud rate")));
        child<QComboBox>(dialog, "baudRate")->setEditText(QStringLiteral("19200"));
        auto *protocol = child<QComboBox>(dialog, "protocol");
        protocol->setCurrentIndex(protocol->findData(int(Protocol::Din66019II)));
        child<QSpinBox>(dialog, "driveAddress")->setValue(12);
        QVERIFY(dialog.validate());
        const ConnectionSettings settings = dialog.settings();
        QCOMPARE(settings.target(), QStringLiteral("serial:/dev/ttyUSB7"));
        QCOMPARE(settings.baudRate, 19200);
        QCOMPARE(settings.protocol, Protocol::Din66019II);
        QCOMPARE(settings.driveAddress, 12);
    }

    void recentConnectionsComeMostRecentFirst()
    {
        ConnectionSettings tcp;
        QVERIFY(tcp.parseTarget(QStringLiteral("tcp:10.0.0.7:4001"), nullptr));
        ConnectionSettings serial;
        QVERIFY(serial.parseTarget(QStringLiteral("serial:/dev/ttyUSB0"), nullptr));
        serial.protocol = Protocol::Din66019II;
        serial.driveAddress = 3;
        RecentConnections::remember(simulated());
        RecentConnections::remember(tcp);
        RecentConnections::remember(serial);
        RecentConnections::remember(tcp); // used again: to the front, not twice
        const QList<ConnectionSettings> recent = RecentConnections::load();
        QCOMPARE(recent.size(), 3);
        QCOMPARE(recent[0].target(), tcp.target());
        QCOMPARE(recent[1].target(), serial.target());
        QCOMPARE(recent[1].driveAddress, 3);
        QCOMPARE(recent[1].protocol, Protocol::Din66019II);
        QCOMPARE(recent[2].kind, ConnectionSettings::Kind::Simulated);

        // The dialog opens on the last one and offers all three.
        ConnectionDialog dialog;
        QCOMPARE(dialog.settings().target(), tcp.target());
        auto *list = child<QListWidget>(dialog, "recentConnections");
        QCOMPARE(list->count(), 3);
        list->setCurrentRow(1);
        QCOMPARE(dialog.settings().target(), serial.target());
        QCOMPARE(dialog.settings().driveAddress, 3);
    }

    void hsp5ExtensionsAreAnOptInRemembered()
    {
        ConnectionDialog dialog;
        auto *extensions = child<QCheckBox>(dialog, "hsp5Extensions");
        auto *protocol = child<QComboBox>(dialog, "protocol");
        protocol->setCurrentIndex(protocol->findData(int(Protocol::Hsp5)));
        QVERIFY(!extensions->isChecked()); // off unless asked for
        QVERIFY(extensions->isEnabled());
        QVERIFY(!dialog.settings().hsp5Extensions);
        extensions->setChecked(true);
        QVERIFY(dialog.settings().hsp5Extensions);
        QVERIFY(dialog.settings().simulation.hsp5Extensions);
        RecentConnections::remember(dialog.settings());
        QVERIFY(RecentConnections::last().hsp5Extensions);
        QVERIFY(ConnectionDialog().settings().hsp5Extensions);

        // DIN66019II frames every request: the option is HSP5's alone.
        protocol->setCurrentIndex(protocol->findData(int(Protocol::Din66019II)));
        QVERIFY(!extensions->isEnabled());
        QVERIFY(!dialog.settings().hsp5Extensions);
    }

    void commandLineNamesTheDrive_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("target");
        QTest::addColumn<QString>("error");
        const auto args = [](const char *text) {
            return QString::fromLatin1(text).split(QLatin1Char(' '), Qt::SkipEmptyParts);
        };
        QTest::newRow("none") << args("drivedesk") << QString() << QString();
        QTest::newRow("sim") << args("drivedesk --connect sim") << QStringLiteral("sim")
                             << QString();
        QTest::newRow("tcp") << args(
            "drivedesk --connect tcp:host:5020 --protocol din66019ii --address 7")
                             << QStringLiteral("tcp:host:5020") << QString();
        QTest::newRow("bad target") << args("drivedesk --connect usb:1") << QString()
                                    << QStringLiteral("unknown connection");
        QTest::newRow("bad protocol") << args("drivedesk --connect sim --protocol modbus")
                                      << QString() << QStringLiteral("unknown protocol \"modbus\"");
        QTest::newRow("bad address") << args("drivedesk --connect sim --address 240") << QString()
                                     << QStringLiteral("--address 240");
        QTest::newRow("bad language") << args("drivedesk --language fr") << QString()
                                      << QStringLiteral("unknown language \"fr\"");
        QTest::newRow("address alone")
            << args("drivedesk --address 3") << QString() << QStringLiteral("belong to --connect");
    }

    void commandLineNamesTheDrive()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, target);
        QFETCH(QString, error);
        const StartupOptions options = StartupOptions::parse(arguments);
        if (!error.isEmpty()) {
            QVERIFY2(options.error.contains(error), qPrintable(options.error));
            return;
        }
        QVERIFY2(options.error.isEmpty(), qPrintable(options.error));
        QCOMPARE(options.connection.has_value(), !target.isEmpty());
        if (options.connection)
            QCOMPARE(options.connection->target(), target);
    }

    void commandLineNamesTheJournal()
    {
        const StartupOptions options = StartupOptions::parse(
            { QStringLiteral("drivedesk"), QStringLiteral("--connect"), QStringLiteral("sim"),
              QStringLiteral("--journal"), QStringLiteral("/srv/machine-7/journal.sqlite") });
        QVERIFY2(options.error.isEmpty(), qPrintable(options.error));
        QCOMPARE(options.journalPath, QStringLiteral("/srv/machine-7/journal.sqlite"));
        QVERIFY(StartupOptions::parse({ QStringLiteral("drivedesk") }).journalPath.isEmpty());
        const StartupOptions empty = StartupOptions::parse(
            { QStringLiteral("drivedesk"), QStringLiteral("--journal"), QString() });
        QVERIFY2(empty.error.contains(QStringLiteral("--journal names a file")),
                 qPrintable(empty.error));
        QVERIFY(StartupOptions::usage().contains(QStringLiteral("--journal PATH")));
    }

    void commandLineLanguageReachesTheDrive()
    {
        const StartupOptions options = StartupOptions::parse(
            { QStringLiteral("drivedesk"), QStringLiteral("--connect"), QStringLiteral("sim"),
              QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
              QStringLiteral("--address"), QStringLiteral("7"), QStringLiteral("--language"),
              QStringLiteral("de") });
        QVERIFY(options.connection);
        QCOMPARE(options.connection->language, Language::German);
        QCOMPARE(options.connection->driveAddress, 7);
        QCOMPARE(options.connection->simulation.driveAddresses, QList<int> { 7 });
        QCOMPARE(options.uiLanguage(), Language::German);

        // Without --language: what was chosen in the menu.
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("de"));
        QCOMPARE(StartupOptions::parse({ QStringLiteral("drivedesk") }).uiLanguage(),
                 Language::German);
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
        QCOMPARE(StartupOptions::parse({ QStringLiteral("drivedesk") }).uiLanguage(),
                 Language::English);
    }

    void theLanguageMenuSaysWhenAChoiceTakesEffect()
    {
        MainWindow window;
        auto *menu = window.findChild<QMenu *>(QStringLiteral("languageMenu"));
        QVERIFY(menu);
        QVERIFY2(menu->title().contains(QLatin1String("next start")), qPrintable(menu->title()));
        QCOMPARE(menu->actions().size(), 2);
        for (QAction *action : menu->actions())
            QVERIFY(action->toolTip().contains(QLatin1String("starts again")));
    }

    // Where the frame and its features put their actions and fields: the menus, the toolbar
    // and the status bar read in this order whatever makes them.
    void theWindowsActionsAndFieldsKeepTheirPlaces()
    {
        MainWindow window;
        const auto names = [](const QList<QAction *> &actions) {
            QStringList shown;
            for (QAction *action : actions) {
                if (action->isSeparator())
                    shown << QStringLiteral("|");
                else if (!action->objectName().isEmpty())
                    shown << action->objectName();
                else
                    shown << action->text().remove(QLatin1Char('&'));
            }
            return shown.join(QLatin1Char(' '));
        };
        const auto menu = [&](const char *name) {
            for (QAction *action : window.menuBar()->actions()) {
                if (action->text() == QLatin1String(name))
                    return names(action->menu()->actions());
            }
            return QString();
        };
        QCOMPARE(menu("&File"),
                 QStringLiteral("openFileAction saveFileAction saveFileAsAction | saveDriveAction "
                                "| exportCsvAction | newPlantAction openPlantAction Open Recent "
                                "Plant | quitAction"));
        QCOMPARE(menu("&Drive"),
                 QStringLiteral("connectAction disconnectAction findDrivesAction | refreshAction "
                                "readMetadataAction | downloadAction pollingAction Polling "
                                "Interval | journalWritesAction | driveInfoAction"));
        QCOMPARE(menu("&Edit"),
                 QStringLiteral("findAction | undoAction redoAction | resetAction "
                                "writeSetsAction copySetAction | passwordAction"));
        // The View menu's windows and docks, after the table's filters and before the language.
        const QString view = menu("&View");
        QVERIFY2(view.endsWith(QStringLiteral("| compareAction | monitorAction scopeViewAction "
                                              "plantViewAction plantHistoryMenuAction "
                                              "journalViewAction | Language (from the next "
                                              "start)")),
                 qPrintable(view));
        QCOMPARE(names(window.toolBar()->actions()),
                 QStringLiteral("connectAction disconnectAction openFileAction saveFileAction | "
                                "refreshAction pollingAction  | undoAction redoAction resetAction "
                                "| passwordAction monitorAction scopeViewAction | "
                                "driveInfoAction"));
        QStringList fields;
        for (QWidget *widget :
             window.statusBar()->findChildren<QWidget *>(Qt::FindDirectChildrenOnly)) {
            if (!widget->objectName().isEmpty())
                fields << widget->objectName();
        }
        QCOMPARE(fields.join(QLatin1Char(' ')),
                 QStringLiteral("metadataSource parameterSets refreshProgress passwordLevel "
                                "connectionState"));
    }

    void findDrivesListsWhatAnswersOnTheBus()
    {
        ConnectionSettings bus = simulated(Protocol::Din66019II);
        bus.baudRate = 115200;
        bus.simulation.driveAddresses = { 1, 3, 7 };
        FindDrivesDialog dialog(bus);
        QSignalSpy finished(&dialog, &FindDrivesDialog::searchFinished);
        QVERIFY(finished.wait(30000));
        QCOMPARE(dialog.foundAddresses(), (QList<int> { 1, 3, 7 }));
        auto *list = child<QListWidget>(dialog, "foundDrives");
        QCOMPARE(list->count(), 3);
        QVERIFY(child<QLabel>(dialog, "searchStatus")->text().contains(QStringLiteral("3 drive")));
        list->setCurrentRow(2);
        dialog.accept();
        QCOMPARE(dialog.chosenAddress(), 7);
    }

    void findDrivesCanBeStopped()
    {
        ConnectionSettings bus = simulated(Protocol::Din66019II);
        bus.simulation.driveAddresses = { 200 };
        FindDrivesDialog dialog(bus);
        auto *progress = child<QProgressBar>(dialog, "searchProgress");
        QTRY_VERIFY_WITH_TIMEOUT(progress->value() > 2, kWaitMs);
        QSignalSpy finished(&dialog, &FindDrivesDialog::searchFinished);
        QTest::mouseClick(child<QPushButton>(dialog, "stopSearch"), Qt::LeftButton);
        QVERIFY(finished.wait(kWaitMs));
        QVERIFY(
            child<QLabel>(dialog, "searchStatus")->text().startsWith(QStringLiteral("Stopped")));
        QVERIFY(dialog.foundAddresses().isEmpty());
        QVERIFY(!dialog.isSearching());
    }

    void windowFindsDrivesOnItsBusAndSwitches()
    {
        MainWindow window;
        ConnectionSettings bus = simulated(Protocol::Din66019II);
        bus.baudRate = 115200;
        bus.simulation.driveAddresses = { 1, 3 };
        QVERIFY(connectAndRead(window, bus));
        QCOMPARE(window.session()->settings().driveAddress, 1);

        bool answered = false;
        QTimer poll;
        connect(&poll, &QTimer::timeout, this, [&] {
            auto *dialog = qobject_cast<FindDrivesDialog *>(QApplication::activeModalWidget());
            if (!dialog || dialog->isSearching() || dialog->foundAddresses().isEmpty())
                return;
            poll.stop();
            answered = true;
            QCOMPARE(dialog->foundAddresses(), (QList<int> { 1, 3 }));
            dialog->findChild<QListWidget *>(QStringLiteral("foundDrives"))->setCurrentRow(1);
            dialog->accept();
        });
        poll.start(20);
        window.findChild<QAction *>(QStringLiteral("findDrivesAction"))->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(answered, kWaitMs);
        // The switch closes the old connection first: until then the window is still ready
        // on drive 1.
        QTRY_VERIFY_WITH_TIMEOUT(window.session() && window.session()->settings().driveAddress == 3
                                     && window.isReady(),
                                 kWaitMs);
        QCOMPARE(RecentConnections::last().driveAddress, 3);
    }

    void driveInformationIsCopyable()
    {
        MainWindow window;
        QVERIFY(connectAndRead(window, simulated()));
        const DriveDescription drive = window.model()->state()->description();
        const QList<DriveInfoDialog::Line> lines
            = DriveInfoDialog::lines(drive, window.session()->settings());
        QStringList labels;
        for (const auto &line : lines)
            labels << line.label;
        // HSP5 has no identification service (seed 000): the drive's identification
        // parameters say what it is.
        QVERIFY(!labels.contains(QStringLiteral("Identification")));
        QVERIFY2(lines.constFirst().label.endsWith(QStringLiteral("(Sy.02)")),
                 qPrintable(lines.constFirst().label));
        const auto version = std::find_if(lines.cbegin(), lines.cend(), [](const auto &line) {
            return line.label.endsWith(QStringLiteral("(In.06)"));
        });
        QVERIFY(version != lines.cend());
        QCOMPARE(version->value, QStringLiteral("1.82"));
        for (const char *id : { "(Sy.02)", "(Sy.03)", "(In.06)", "(In.10)" }) {
            QVERIFY2(std::any_of(labels.cbegin(), labels.cend(),
                                 [id](const QString &label) {
                                     return label.endsWith(QString::fromLatin1(id));
                                 }),
                     id);
        }
        QVERIFY(labels.contains(QStringLiteral("Parameters")));

        DriveInfoDialog dialog(drive, window.session()->settings());
        QTest::mouseClick(child<QPushButton>(dialog, "copyInformation"), Qt::LeftButton);
        const QString copied = QApplication::clipboard()->text();
        QVERIFY(copied.contains(QStringLiteral("Parameters: %1").arg(kSimulatedParameters)));
        QVERIFY(copied.contains(QStringLiteral("Parameter groups: %1").arg(kSimulatedGroups)));
        QCOMPARE(copied, dialog.plainText());
    }
};

QTEST_MAIN(TestMainWindowDialogs)
#include "tst_mainwindow_dialogs.moc"
