#include "PlaintextEditors.h"

#include <QScopedValueRollback>
#include <QStandardItemModel>

namespace DriveDesk {

namespace {

void disableItem(QComboBox *combo, int row, const QString &reason)
{
    if (auto *items = qobject_cast<QStandardItemModel *>(combo->model())) {
        QStandardItem *item = items->item(row);
        item->setEnabled(false);
        item->setToolTip(reason);
    }
}

} // namespace

PlaintextComboBox::PlaintextComboBox(const ParameterFormat &format, QWidget *parent)
    : QComboBox(parent)
    , ValueEditor(format)
{
    connect(this, &QComboBox::activated, this, [this] {
        if (!m_stepping)
            emit picked();
    });
}

void PlaintextComboBox::setRawValue(qint32 raw)
{
    clear();
    const PlaintextDefinition *definition = nullptr;
    for (const PlaintextDefinition &candidate : format().plaintexts().definitions()) {
        if (!candidate.entries.isEmpty()) {
            definition = &candidate;
            break;
        }
    }
    if (!definition)
        return;
    const quint32 mask = Plaintexts::effectiveMask(*definition);
    const PlaintextEntry *current = Plaintexts::match(*definition, raw);
    int currentRow = -1;
    for (const PlaintextEntry &entry : definition->entries) {
        // As Plaintexts::value(): an entry with bits outside the mask is the whole value.
        const qint32 value = (quint32(entry.value) & ~mask)
            ? entry.value
            : qint32((quint32(raw) & ~mask) | quint32(entry.value));
        if (&entry == current)
            currentRow = count();
        addItem(entry.text, value);
        if (!format().isWithinLimits(value) && &entry != current)
            disableItem(this, count() - 1, format().limitsProblem(value));
    }
    if (currentRow < 0) {
        insertItem(0, format().text(raw), raw);
        currentRow = 0;
    }
    setCurrentIndex(currentRow);
}

std::optional<qint32> PlaintextComboBox::editedValue(QString *problem) const
{
    if (currentIndex() < 0) {
        if (problem)
            *problem = tr("no text chosen");
        return std::nullopt;
    }
    return currentData().toInt();
}

void PlaintextComboBox::keyPressEvent(QKeyEvent *event)
{
    const QScopedValueRollback stepping(m_stepping, true);
    QComboBox::keyPressEvent(event);
}

void PlaintextComboBox::wheelEvent(QWheelEvent *event)
{
    const QScopedValueRollback stepping(m_stepping, true);
    QComboBox::wheelEvent(event);
}

} // namespace DriveDesk
