#include "tst_scopesupport.h"

#include "plant/PlantDock.h"
#include "plant/PlantFeature.h"
#include "plant/PlantFile.h"
#include "scope/ScopeChannelPanel.h"
#include "scope/ScopeChart.h"
#include "scope/ScopeDock.h"
#include "scope/ScopePresetLibrary.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QInputDialog>
#include <QMessageBox>
#include <QLabel>
#include <QMenu>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;
using namespace DriveDesk::ScopeDockTest;

namespace {


template<typename Widget>
Widget *child(ScopeDock &dock, const char *name)
{
    return dock.findChild<Widget *>(QLatin1String(name));
}

QString status(ScopeDock &dock)
{
    return child<QLabel>(dock, "scopeStatus")->text();
}

// The Presets menu as it shows when opened.
QMenu *openedPresetMenu(ScopeDock &dock)
{
    auto *menu = child<QMenu>(dock, "scopePresetMenu");
    if (menu)
        emit menu->aboutToShow();
    return menu;
}

// Save Preset As..., the name typed into the dialog it shows, OK.
bool savePresetAs(ScopeDock &dock, const QString &name)
{
    QMenu *menu = openedPresetMenu(dock);
    QAction *save = menu ? menu->findChild<QAction *>(QStringLiteral("scopeSavePresetAction")) : nullptr;
    if (!save || !save->isEnabled())
        return false;
    save->trigger();
    QInputDialog *dialog = nullptr;
    if (!QTest::qWaitFor([&] {
            dialog = dock.findChild<QInputDialog *>(QStringLiteral("scopePresetNameDialog"));
            return dialog && dialog->isVisible();
        }, kWaitMs))
        return false;
    dialog->setTextValue(name);
    dialog->accept();
    return true;
}

// The presets the menu offers to load, as it names them.
QStringList offeredPresets(ScopeDock &dock)
{
    QStringList names;
    for (QAction *action : openedPresetMenu(dock)->actions()) {
        if (action->objectName() == QLatin1String("scopePresetAction"))
            names << action->text();
    }
    return names;
}

bool loadPreset(ScopeDock &dock, const QString &text)
{
    for (QAction *action : openedPresetMenu(dock)->actions()) {
        if (action->objectName() == QLatin1String("scopePresetAction") && action->text() == text
            && action->isEnabled()) {
            action->trigger();
            return true;
        }
    }
    return false;
}

} // namespace

// Scope presets in the window, against the simulated drive: a set-up saved under a name comes
// back whole after it was changed; a source the drive does not have is said, the rest loads;
// with a plant open, the preset is kept beside the plant file.
class TestScopePresets : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    QTemporaryDir m_data;

private slots:
    void initTestCase()
    {
        // The presets the window saves go to a folder of the test's own.
        qputenv("XDG_DATA_HOME", m_data.path().toLocal8Bit());
    }

    void init()
    {
        m_settings.clear();
        QDir(ScopePresetLibrary::userFolder()).removeRecursively();
    }

    void aSavedPresetLoadsTheSetUpBack()
    {
        MainWindow window;
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        auto *dock = window.findChild<ScopeDock *>();
        ScopeChannelPanel *panel = dock->channelPanel();
        chooseSource(*dock, 0, kDcLinkVoltage);
        chooseSource(*dock, 1, kMaxSpeedForward);
        child<QComboBox>(*dock, "scopeSet2")->setCurrentIndex(2);
        panel->setChannelColor(1, QColor(0x11, 0x22, 0x33));
        panel->setChannelVisible(0, false);
        panel->setOwnAxis(1, true);
        child<QComboBox>(*dock, "scopeTriggerChannel")->setCurrentIndex(1);
        child<QComboBox>(*dock, "scopeTriggerEdge")->setCurrentIndex(1);
        child<QDoubleSpinBox>(*dock, "scopeTriggerLevel")->setValue(1500);
        child<QSpinBox>(*dock, "scopeTriggerPre")->setValue(35);
        child<QDoubleSpinBox>(*dock, "scopeTriggerWindow")->setValue(2.5);
        child<QDoubleSpinBox>(*dock, "scopeRollSeconds")->setValue(4.5);
        child<QSpinBox>(*dock, "scopeRateLimit")->setValue(250);

        QVERIFY(savePresetAs(*dock, QStringLiteral("Speed step")));
        const QString file = ScopePresetLibrary::userFolder() + QStringLiteral("/Speed step.json");
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(file), kWaitMs);
        QVERIFY2(status(*dock).contains(QStringLiteral("Preset 'Speed step' saved")),
                 qPrintable(status(*dock)));
        // Made for this kind of drive: another kind's list leaves it out.
        const std::optional<ScopePreset> saved = ScopePresetFile::load(file);
        QVERIFY(saved && !saved->driveKind.isEmpty());
        QVERIFY(ScopePresetLibrary().list(QStringLiteral("another kind")).isEmpty());

        // Everything changed, then the preset loaded again.
        chooseSource(*dock, 0, kOutputVoltage);
        chooseSource(*dock, 1, kOutputVoltage);
        panel->setChannelColor(1, QColor(Qt::red));
        panel->setChannelVisible(0, true);
        panel->setOwnAxis(1, false);
        child<QComboBox>(*dock, "scopeTriggerChannel")->setCurrentIndex(3);
        child<QComboBox>(*dock, "scopeTriggerEdge")->setCurrentIndex(0);
        child<QDoubleSpinBox>(*dock, "scopeTriggerLevel")->setValue(7);
        child<QSpinBox>(*dock, "scopeTriggerPre")->setValue(10);
        child<QDoubleSpinBox>(*dock, "scopeTriggerWindow")->setValue(1);
        child<QDoubleSpinBox>(*dock, "scopeRollSeconds")->setValue(10);
        child<QSpinBox>(*dock, "scopeRateLimit")->setValue(0);

        QCOMPARE(offeredPresets(*dock), QStringList{QStringLiteral("Speed step")});
        QVERIFY(loadPreset(*dock, QStringLiteral("Speed step")));
        QCOMPARE(status(*dock), QStringLiteral("Preset 'Speed step' loaded."));
        // What the window does next (the connection's news) leaves the outcome said.
        dock->updateActions();
        QCOMPARE(status(*dock), QStringLiteral("Preset 'Speed step' loaded."));
        QCOMPARE(panel->choices()[0],
                 std::optional<ChannelAssignment>(ChannelAssignment{kDcLinkVoltage, 0x01}));
        QCOMPARE(panel->choices()[1],
                 std::optional<ChannelAssignment>(ChannelAssignment{kMaxSpeedForward, 0x04}));
        QCOMPARE(child<QComboBox>(*dock, "scopeSet2")->currentText(), QStringLiteral("2"));
        QVERIFY(!panel->choices()[2]); // as the drive has it, as before
        QCOMPARE(panel->channelColor(1), QColor(0x11, 0x22, 0x33));
        QVERIFY(!panel->isChannelVisible(0));
        QVERIFY(!dock->chart()->isChannelVisible(0));
        QVERIFY(panel->hasOwnAxis(1));
        QVERIFY(dock->chart()->hasChannelOwnAxis(1));
        QCOMPARE(child<QComboBox>(*dock, "scopeTriggerChannel")->currentIndex(), 1);
        QCOMPARE(child<QComboBox>(*dock, "scopeTriggerEdge")->currentIndex(), 1);
        QCOMPARE(child<QDoubleSpinBox>(*dock, "scopeTriggerLevel")->value(), 1500.0);
        QCOMPARE(child<QSpinBox>(*dock, "scopeTriggerPre")->value(), 35);
        QCOMPARE(child<QDoubleSpinBox>(*dock, "scopeTriggerWindow")->value(), 2.5);
        QCOMPARE(child<QDoubleSpinBox>(*dock, "scopeRollSeconds")->value(), 4.5);
        QCOMPARE(child<QSpinBox>(*dock, "scopeRateLimit")->value(), 250);
    }

    void aSourceTheDriveLacksIsSaidAndTheRestLoads()
    {
        MainWindow window;
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        auto *dock = window.findChild<ScopeDock *>();
        ScopePreset preset = dock->currentPreset(QStringLiteral("Other drive"));
        preset.channels[0].source = ScopeSourceText::parse(QStringLiteral("ru.9"));
        preset.channels[2].source = ScopeSourceText::parse(QStringLiteral("zz.3"));
        preset.channels[3].source = ScopeSourceText::parse(QStringLiteral("Sy.16"));
        preset.rateLimitHz = 125;
        QVERIFY(ScopePresetLibrary().save(preset, nullptr));

        QVERIFY(loadPreset(*dock, QStringLiteral("Other drive")));
        const QString said = status(*dock);
        QVERIFY2(said.contains(QStringLiteral("Channel 3 (zz.3)"))
                     && said.contains(QStringLiteral("zz"))
                     && said.contains(QStringLiteral("Channel 4 (Sy.16)")),
                 qPrintable(said));
        ScopeChannelPanel *panel = dock->channelPanel();
        QCOMPARE(panel->choices()[0],
                 std::optional<ChannelAssignment>(ChannelAssignment{kOutputVoltage, 0x01}));
        QCOMPARE(panel->choices()[2], std::optional<ChannelAssignment>(ChannelAssignment{}));
        QCOMPARE(panel->choices()[3], std::optional<ChannelAssignment>(ChannelAssignment{}));
        QCOMPARE(child<QSpinBox>(*dock, "scopeRateLimit")->value(), 125);
        // Nothing went to the drive: the assignment is written at Record.
        QVERIFY(!dock->isRecording());
    }

    void aPresetOfTheSameNameIsReplacedOnlyWhenTheUserSaysSo()
    {
        MainWindow window;
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        auto *dock = window.findChild<ScopeDock *>();
        chooseSource(*dock, 0, kDcLinkVoltage);
        QVERIFY(savePresetAs(*dock, QStringLiteral("Speed step")));
        const QString file = ScopePresetLibrary::userFolder() + QStringLiteral("/Speed step.json");
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(file), kWaitMs);
        const auto firstSource = [&file] {
            const std::optional<ScopePreset> preset = ScopePresetFile::load(file);
            return preset && preset->channels[0].source ? preset->channels[0].source->text()
                                                        : QString();
        };
        QCOMPARE(firstSource(), QStringLiteral("ru.18"));

        const auto question = [dock] {
            QMessageBox *box = nullptr;
            const bool shown = QTest::qWaitFor([&] {
                box = dock->findChild<QMessageBox *>(QStringLiteral("scopePresetReplaceQuestion"));
                return box && box->isVisible();
            }, kWaitMs);
            return shown ? box : nullptr;
        };
        // Asked, and cancelled: the preset on file stays as it was.
        chooseSource(*dock, 0, kOutputVoltage);
        QVERIFY(savePresetAs(*dock, QStringLiteral("Speed step ")));
        QMessageBox *asked = question();
        QVERIFY(asked);
        QVERIFY2(asked->text().contains(QStringLiteral("'Speed step' is already saved")),
                 qPrintable(asked->text()));
        asked->button(QMessageBox::Cancel)->click();
        QTRY_VERIFY_WITH_TIMEOUT(!dock->findChild<QMessageBox *>(
                                     QStringLiteral("scopePresetReplaceQuestion")),
                                 kWaitMs);
        QCOMPARE(firstSource(), QStringLiteral("ru.18"));

        // Asked again, and replaced.
        QVERIFY(savePresetAs(*dock, QStringLiteral("Speed step")));
        asked = question();
        QVERIFY(asked);
        QAbstractButton *replace = nullptr;
        for (QAbstractButton *button : asked->buttons()) {
            if (asked->buttonRole(button) == QMessageBox::AcceptRole)
                replace = button;
        }
        QVERIFY(replace);
        replace->click();
        QTRY_COMPARE_WITH_TIMEOUT(firstSource(), QStringLiteral("ru.09"), kWaitMs);
        QVERIFY2(status(*dock).contains(QStringLiteral("Preset 'Speed step' saved")),
                 qPrintable(status(*dock)));
    }

    void withAPlantOpenThePresetIsKeptBesideIt()
    {
        QTemporaryDir dir;
        const QString plantPath = dir.filePath(QStringLiteral("line3.json"));
        Plant plant;
        plant.name = QStringLiteral("Line 3");
        PlantLink link;
        link.name = QStringLiteral("cabinet");
        link.connect = QStringLiteral("sim");
        plant.links = {link};
        QString error;
        QVERIFY2(PlantFile::save(plantPath, plant, &error), qPrintable(error));

        MainWindow window;
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        auto *dock = window.findChild<ScopeDock *>();
        QVERIFY(savePresetAs(*dock, QStringLiteral("Everyone's")));
        QVERIFY(window.findChild<PlantFeature *>()->openPlant(plantPath));
        chooseSource(*dock, 0, kDcLinkVoltage);
        QVERIFY(savePresetAs(*dock, QStringLiteral("DC link")));
        const QString beside = dir.filePath(QStringLiteral("line3.scope-presets/DC link.json"));
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(beside), kWaitMs);
        QVERIFY(!QFile::exists(ScopePresetLibrary::userFolder() + QStringLiteral("/DC link.json")));
        // The plant's first, then the user's own.
        QCOMPARE(offeredPresets(*dock),
                 (QStringList{QStringLiteral("DC link (plant)"), QStringLiteral("Everyone's")}));
        QVERIFY(ScopePresetFile::load(beside)->channels[0].source->text() == QStringLiteral("ru.18"));
    }
};

QTEST_MAIN(TestScopePresets)
#include "tst_scopepresets.moc"
