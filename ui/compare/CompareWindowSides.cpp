// CompareWindow: each side read as it is now, and the two compared.
#include "CompareWindow.h"

#include "CompareHost.h"
#include "ComparePaths.h"
#include "ComparisonFilterModel.h"
#include "ComparisonModel.h"

#include "model/ParameterModel.h"
#include "parameters/ParameterComparison.h"
#include "parameters/ParameterDocument.h"

#include <QComboBox>
#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QTreeView>

namespace DriveDesk {

std::optional<CompareWindow::Side> CompareWindow::readSide(bool a, const Side *sideA,
                                                           QString *error) const
{
    const SideWidgets &widgets = a ? m_sideA : m_sideB;
    const QString letter = a ? tr("A") : tr("B");
    Side side;
    side.source = sourceOf(a);
    switch (side.source) {
    case Source::Drive:
        if (!m_host || !m_host->hasDrive()) {
            *error = tr("Side %1: no drive is connected and read.").arg(letter);
            return std::nullopt;
        }
        side.description = m_host->drive();
        side.name = tr("the drive");
        break;
    case Source::ShownFile:
        if (!m_host || m_host->shownFilePath().isEmpty()) {
            *error = tr("Side %1: the window shows no parameter file.").arg(letter);
            return std::nullopt;
        }
        side.path = m_host->shownFilePath();
        side.description = m_host->shownFile();
        side.name = tr("%1 (shown)").arg(QFileInfo(side.path).fileName());
        break;
    case Source::File: {
        side.path = widgets.path->text().trimmed();
        if (side.path.isEmpty()) {
            *error = tr("Side %1: choose a parameter file.").arg(letter);
            return std::nullopt;
        }
        QString problem;
        const std::optional<DriveDescription> drive = ParameterDocument::load(side.path, &problem);
        if (!drive) {
            *error = tr("Side %1: could not read the file: %2").arg(letter, problem);
            return std::nullopt;
        }
        side.description = *drive;
        side.name = QFileInfo(side.path).fileName();
        if (!widgets.readingName.isEmpty() && side.path == widgets.readingPath) {
            side.name = widgets.readingName;
            side.writable = false;
            side.reading = true;
        }
        // The window's own file is compared as the window holds it, unsaved changes and all.
        if (m_host && samePath(side.path, m_host->shownFilePath())) {
            side.source = Source::ShownFile;
            side.description = m_host->shownFile();
            side.name = tr("%1 (shown)").arg(side.name);
        }
        break;
    }
    case Source::Defaults:
        side = *sideA;
        side.source = Source::Defaults;
        side.description = defaultsOf(sideA->origin);
        side.name = tr("defaults of %1").arg(sideA->name);
        side.writable = false;
        return side;
    case Source::SameAsA:
        return *sideA;
    }
    side.origin = side.description;
    return side;
}

bool CompareWindow::compare()
{
    QString error;
    std::optional<Side> a = readSide(true, nullptr, &error);
    std::optional<Side> b = a ? readSide(false, &*a, &error) : std::nullopt;
    if (!a || !b) {
        showMessage(error);
        return false;
    }
    // Against its defaults a side shows only the values a user sets, as the command line's
    // diff does: live values and counters have no default to go back to.
    if (b->source == Source::Defaults)
        a->description = userSettingsOf(a->origin);
    const bool setAgainstSet = m_setAgainstSet->isChecked();
    const ComparisonTable table = setAgainstSet
        ? compareSets(a->description, m_sideA.set->value(), b->description, m_sideB.set->value())
        : compareAll(a->description, b->description);
    m_a = a;
    m_b = b;
    m_model->setComparison(table, a->description, b->description);
    QString nameA = a->name;
    QString nameB = b->name;
    if (setAgainstSet) {
        nameA = tr("%1, set %2").arg(nameA).arg(m_sideA.set->value());
        nameB = tr("%1, set %2").arg(nameB).arg(m_sideB.set->value());
    }
    m_model->setSideNames(nameA, nameB);

    const QString group = m_groupBox->currentData().toString();
    m_groupBox->blockSignals(true);
    m_groupBox->clear();
    m_groupBox->addItem(tr("All groups"), QString());
    for (int g = 0; g < m_model->rowCount(); ++g) {
        const QModelIndex index = m_model->index(g, 0);
        m_groupBox->addItem(index.data().toString(),
                            index.data(ParameterModel::GroupIdRole).toString());
    }
    m_groupBox->setCurrentIndex(std::max(0, m_groupBox->findData(group)));
    m_groupBox->blockSignals(false);
    m_filter->setGroup(m_groupBox->currentData().toString());

    expandGroups();
    updateWriteButtons();
    QString said = tr("Compared %1 with %2: %n value(s) differ.", nullptr,
                      table.count(ComparisonRow::State::Different))
                       .arg(nameA, nameB);
    if (a->reading || b->reading) {
        said += QLatin1Char(' ')
            + tr("A drive read for this comparison is not written to here: open the drive in "
                 "the editor to change it.");
    }
    showMessage(said);
    return true;
}

} // namespace DriveDesk
