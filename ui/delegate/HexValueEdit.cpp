#include "HexValueEdit.h"

#include <QRegularExpressionValidator>

namespace DriveDesk {

HexValueEdit::HexValueEdit(const ParameterFormat &format, QWidget *parent)
    : QLineEdit(parent)
    , ValueEditor(format)
{
    static const QRegularExpression pattern(
        QStringLiteral("\\s*(0[xX])?[0-9A-Fa-f]{0,8}[hH]?\\s*"));
    setValidator(new QRegularExpressionValidator(pattern, this));
    setToolTip(tr("Hexadecimal, %1 .. %2")
                   .arg(format.number(format.minimum()), format.number(format.maximum())));
}

void HexValueEdit::setRawValue(qint32 raw)
{
    setText(format().number(raw, false));
}

std::optional<qint32> HexValueEdit::editedValue(QString *problem) const
{
    return format().parse(text(), problem, ParameterFormat::Limits::Ignore);
}

} // namespace DriveDesk
