#include "PlaintextEditors.h"

#include <QHBoxLayout>
#include <QStandardItemModel>

namespace DriveDesk {

namespace {

QString hexBits(quint32 bits)
{
    return QString::number(bits, 16).toUpper().rightJustified(bits > 0xFFFF ? 8 : 4,
                                                              QLatin1Char('0'))
        + QLatin1Char('h');
}

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
{ }

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

BitFieldEditor::BitFieldEditor(const ParameterFormat &format, QWidget *parent)
    : QWidget(parent)
    , ValueEditor(format)
{
    setAutoFillBackground(true);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    const QList<PlaintextDefinition> &definitions = format.plaintexts().definitions();
    for (qsizetype i = 0; i < definitions.size(); ++i) {
        const PlaintextDefinition &definition = definitions.at(i);
        if (definition.entries.isEmpty())
            continue;
        auto *combo = new QComboBox(this);
        combo->setToolTip(definition.description.isEmpty() ? tr("Definition %1").arg(i)
                                                           : definition.description);
        combo->setAccessibleName(combo->toolTip());
        layout->addWidget(combo);
        m_fields << combo;
        m_definitions << definition;
        m_covered |= Plaintexts::effectiveMask(definition);
    }
    if (!m_fields.isEmpty())
        setFocusProxy(m_fields.first());
}

void BitFieldEditor::setRawValue(qint32 raw)
{
    m_start = raw;
    for (qsizetype i = 0; i < m_fields.size(); ++i) {
        QComboBox *combo = m_fields.at(i);
        const PlaintextDefinition &definition = m_definitions.at(i);
        const quint32 mask = Plaintexts::effectiveMask(definition);
        const PlaintextEntry *current = Plaintexts::match(definition, raw);
        combo->clear();
        int currentRow = -1;
        for (const PlaintextEntry &entry : definition.entries) {
            if (&entry == current)
                currentRow = combo->count();
            combo->addItem(entry.text, quint32(entry.value) & mask);
        }
        if (currentRow < 0) {
            const quint32 bits = quint32(raw) & mask;
            combo->insertItem(0, tr("%1 (no plaintext)").arg(hexBits(bits)), bits);
            currentRow = 0;
        }
        combo->setCurrentIndex(currentRow);
    }
}

std::optional<qint32> BitFieldEditor::editedValue(QString *) const
{
    quint32 value = quint32(m_start) & ~m_covered;
    for (qsizetype i = 0; i < m_fields.size(); ++i) {
        const quint32 mask = Plaintexts::effectiveMask(m_definitions.at(i));
        value |= m_fields.at(i)->currentData().toUInt() & mask;
    }
    return qint32(value);
}

} // namespace DriveDesk
