#include "BitFieldEditor.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGuiApplication>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QVBoxLayout>

namespace DriveDesk {

namespace {

QString hexBits(quint32 bits)
{
    return QString::number(bits, 16).toUpper().rightJustified(bits > 0xFFFF ? 8 : 4,
                                                              QLatin1Char('0'))
        + QLatin1Char('h');
}

} // namespace

BitFieldEditor::BitFieldEditor(const ParameterFormat &format, QWidget *parent)
    : QFrame(parent, Qt::Popup)
    , ValueEditor(format)
{
    setFrameStyle(QFrame::StyledPanel | QFrame::Raised);
    setAutoFillBackground(true);
    auto *layout = new QVBoxLayout(this);

    m_title = new QLabel(this);
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    m_title->hide();
    layout->addWidget(m_title);

    auto *form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    const QList<PlaintextDefinition> &definitions = format.plaintexts().definitions();
    for (qsizetype i = 0; i < definitions.size(); ++i) {
        const PlaintextDefinition &definition = definitions.at(i);
        if (definition.entries.isEmpty())
            continue;
        const QString name = definition.description.isEmpty() ? tr("Definition %1").arg(i)
                                                               : definition.description;
        auto *combo = new QComboBox(this);
        combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);
        combo->setAccessibleName(name);
        auto *label = new QLabel(tr("%1:").arg(name), this);
        label->setBuddy(combo);
        form->addRow(label, combo);
        connect(combo, &QComboBox::currentIndexChanged, this, &BitFieldEditor::showComposedValue);
        m_fields << combo;
        m_labels << label;
        m_definitions << i;
    }
    layout->addLayout(form);

    m_composed = new QLabel(this);
    m_composed->setWordWrap(true);
    layout->addWidget(m_composed);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    // Enter on a button presses it; elsewhere it writes (the delegate sees it).
    for (QAbstractButton *button : buttons->buttons()) {
        if (auto *push = qobject_cast<QPushButton *>(button))
            push->setAutoDefault(true);
    }
    connect(buttons, &QDialogButtonBox::accepted, this, &BitFieldEditor::accepted);
    connect(buttons, &QDialogButtonBox::rejected, this, &BitFieldEditor::rejected);
    layout->addWidget(buttons);

    if (!m_fields.isEmpty())
        setFocusProxy(m_fields.first());
}

void BitFieldEditor::setTitle(const QString &title)
{
    m_title->setText(title);
    m_title->setVisible(!title.isEmpty());
}

void BitFieldEditor::placeAt(const QRect &cell)
{
    m_cell = cell;
    if (QLayout *content = layout())
        content->activate();
    QSize size = sizeHint().expandedTo(QSize(cell.width(), 0)).expandedTo(minimumSizeHint());
    if (hasHeightForWidth())
        size.setHeight(std::max(size.height(), heightForWidth(size.width())));
    QRect rect(cell.topLeft(), size);
    if (const QScreen *screen = QGuiApplication::screenAt(cell.center())) {
        const QRect room = screen->availableGeometry();
        rect.moveRight(std::min(rect.right(), room.right()));
        rect.moveBottom(std::min(rect.bottom(), room.bottom()));
        rect.moveLeft(std::max(rect.left(), room.left()));
        rect.moveTop(std::max(rect.top(), room.top()));
    }
    setGeometry(rect);
}

void BitFieldEditor::setRawValue(qint32 raw)
{
    m_start = raw;
    const QList<PlaintextDefinition> &definitions = format().plaintexts().definitions();
    for (qsizetype i = 0; i < m_fields.size(); ++i) {
        QComboBox *combo = m_fields.at(i);
        const PlaintextDefinition &definition = definitions.at(m_definitions.at(i));
        const quint32 mask = Plaintexts::effectiveMask(definition);
        const PlaintextEntry *current = Plaintexts::match(definition, raw);
        const QSignalBlocker blocker(combo);
        combo->clear();
        int currentRow = -1;
        for (const PlaintextEntry &entry : definition.entries) {
            if (&entry == current)
                currentRow = combo->count();
            combo->addItem(entry.text, entry.value);
        }
        if (currentRow < 0) {
            const quint32 bits = quint32(raw) & mask;
            combo->insertItem(0, tr("%1 (no plaintext)").arg(hexBits(bits)), qint32(bits));
            currentRow = 0;
        }
        combo->setCurrentIndex(currentRow);
    }
    showComposedValue();
}

std::optional<qint32> BitFieldEditor::editedValue(QString *) const
{
    const Plaintexts &plaintexts = format().plaintexts();
    qint32 value = m_start;
    for (qsizetype i = 0; i < m_fields.size(); ++i)
        value = plaintexts.withField(value, m_definitions.at(i), m_fields.at(i)->currentData().toInt());
    return value;
}

void BitFieldEditor::showComposedValue()
{
    QString problem;
    const std::optional<qint32> raw = rawValue(&problem);
    m_composed->setText(raw ? tr("Value: %1").arg(format().text(*raw)) : problem);
    if (m_cell.isValid())
        placeAt(m_cell); // the content may need more room now
}

} // namespace DriveDesk
