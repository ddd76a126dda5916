#pragma once

#include "ValueEditor.h"

#include <QLineEdit>

namespace DriveDesk {

// A line edit for parameters shown in hexadecimal: up to 8 hex digits, "0x" or "h" optional.
class HexValueEdit : public QLineEdit, public ValueEditor
{
    Q_OBJECT
public:
    explicit HexValueEdit(const ParameterFormat &format, QWidget *parent = nullptr);

protected:
    void setRawValue(qint32 raw) override;
    std::optional<qint32> editedValue(QString *problem) const override;
};

} // namespace DriveDesk
