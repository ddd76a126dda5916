#pragma once

// What the scope dock's tests share: the simulated F5's sources they record, choosing one in a
// channel's row, the dock's actions by name, the legend's names, and a math channel added from
// the dock's menu. With tst_mainwindow_support.h.
#include "tst_mainwindow_support.h"

#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeDock.h"
#include "scope/ScopeMathDefinition.h"
#include "scope/ScopeMathDialog.h"

#include <QAction>
#include <QComboBox>

namespace DriveDesk::ScopeDockTest {

// Sources of the simulated F5 (core/sim/data/sim_f5_parameters.csv).
constexpr quint16 kActualFrequency = 0x0203; // ru.03, 0.01 Hz
constexpr quint16 kActualSpeed = 0x0207;     // ru.07, 1/min
constexpr quint16 kOutputVoltage = 0x0209;   // ru.09, V
constexpr quint16 kDcLinkVoltage = 0x0212;   // ru.18, V
constexpr quint16 kMaxSpeedForward = 0x030B; // op.11, 8 sets

// `address` chosen as the source of `channel` (0-3) in the dock's panel.
inline void chooseSource(ScopeDock &dock, int channel, int address)
{
    auto *box = dock.findChild<QComboBox *>(QStringLiteral("scopeSource%1").arg(channel + 1));
    QVERIFY(box);
    const int index = box->findData(address);
    QVERIFY2(index >= 0, qPrintable(QStringLiteral("no source %1").arg(address)));
    box->setCurrentIndex(index);
}

inline QAction *action(ScopeDock &dock, const char *name)
{
    return dock.findChild<QAction *>(QLatin1String(name));
}

inline QStringList legendNames(const QCustomPlot *plot)
{
    QStringList names;
    for (int i = 0; i < plot->legend->itemCount(); ++i) {
        if (auto *item = qobject_cast<QCPPlottableLegendItem *>(plot->legend->item(i)))
            names << item->plottable()->name();
    }
    return names;
}

// Add Math Channel's dialog, opened from the dock and set to the derivative of the first
// channel; nullptr if it did not come.
inline ScopeMathDialog *derivativeOfTheFirstChannel(ScopeDock &dock)
{
    action(dock, "scopeAddMathAction")->trigger();
    ScopeMathDialog *dialog = nullptr;
    if (!QTest::qWaitFor([&] { return (dialog = dock.findChild<ScopeMathDialog *>()) != nullptr
                                      && dialog->isVisible(); },
                         MainWindowTest::kWaitMs))
        return nullptr;
    auto *kind = dialog->findChild<QComboBox *>(QStringLiteral("scopeMathKind"));
    kind->setCurrentIndex(kind->findData(int(ScopeMathDefinition::Kind::Derivative)));
    dialog->findChild<QComboBox *>(QStringLiteral("scopeMathFirst"))->setCurrentIndex(0);
    return dialog;
}

} // namespace DriveDesk::ScopeDockTest
