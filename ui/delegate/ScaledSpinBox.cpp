#include "ScaledSpinBox.h"

#include <QLineEdit>

namespace DriveDesk {

ScaledSpinBox::ScaledSpinBox(const ParameterFormat &format, QWidget *parent)
    : QSpinBox(parent)
    , ValueEditor(format)
{
    setRange(format.minimum(), format.maximum());
    setSingleStep(1);
    setAccelerated(true);
    const QString unit = format.isRaw() ? QString() : format.scaling().unitSymbol();
    if (!unit.isEmpty())
        setSuffix(QLatin1Char(' ') + unit);
    if (!format.isRaw()) {
        const std::optional<double> low = format.scaling().toDisplay(format.minimum());
        const std::optional<double> high = format.scaling().toDisplay(format.maximum());
        m_reversed = low && high && *low > *high;
    }
    setToolTip(
        tr("%1 .. %2")
            .arg(format.number(format.minimum(), true), format.number(format.maximum(), true)));
}

int ScaledSpinBox::decimals() const
{
    return format().isRaw() ? 0 : format().scaling().decimals();
}

void ScaledSpinBox::setRawValue(qint32 raw)
{
    if (raw >= minimum() && raw <= maximum()) {
        setValue(raw);
        return;
    }
    // Shown as it is, not clamped: the spin box must not invent a value the drive does not hold.
    lineEdit()->setText(textFromValue(raw) + suffix());
}

std::optional<qint32> ScaledSpinBox::editedValue(QString *problem) const
{
    return format().parse(lineEdit()->text(), problem, ParameterFormat::Limits::Ignore);
}

QValidator::State ScaledSpinBox::validate(QString &input, int &) const
{
    QString problem;
    const std::optional<qint32> raw
        = format().parse(input, &problem, ParameterFormat::Limits::Ignore);
    if (raw && (*raw == initialValue() || format().isWithinLimits(*raw)))
        return QValidator::Acceptable;
    // Typing goes on; committing is refused with the reason.
    return QValidator::Intermediate;
}

int ScaledSpinBox::valueFromText(const QString &text) const
{
    return format().parse(text, nullptr, ParameterFormat::Limits::Ignore).value_or(value());
}

QString ScaledSpinBox::textFromValue(int value) const
{
    return format().number(value, false);
}

void ScaledSpinBox::fixup(QString &) const
{
    // Nothing is corrected behind the user's back.
}

void ScaledSpinBox::stepBy(int steps)
{
    QSpinBox::stepBy(m_reversed ? -steps : steps);
}

QAbstractSpinBox::StepEnabled ScaledSpinBox::stepEnabled() const
{
    const StepEnabled enabled = QSpinBox::stepEnabled();
    if (!m_reversed)
        return enabled;
    StepEnabled swapped = StepNone;
    if (enabled & StepUpEnabled)
        swapped |= StepDownEnabled;
    if (enabled & StepDownEnabled)
        swapped |= StepUpEnabled;
    return swapped;
}

} // namespace DriveDesk
