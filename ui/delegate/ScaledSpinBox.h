#pragma once

#include "ValueEditor.h"

#include <QSpinBox>

namespace DriveDesk {

// A spin box over raw values: it steps one raw step at a time within the limits and shows the
// value scaled, with the parameter's decimals and unit. A typed number is taken only when the
// table would show it as typed; otherwise value() gives the reason and the text stays.
class ScaledSpinBox : public QSpinBox, public ValueEditor
{
    Q_OBJECT
public:
    explicit ScaledSpinBox(const ParameterFormat &format, QWidget *parent = nullptr);

    int decimals() const;
    void stepBy(int steps) override;

protected:
    void setRawValue(qint32 raw) override;
    std::optional<qint32> editedValue(QString *problem) const override;

    QValidator::State validate(QString &input, int &pos) const override;
    int valueFromText(const QString &text) const override;
    QString textFromValue(int value) const override;
    void fixup(QString &input) const override;
    StepEnabled stepEnabled() const override;

private:
    bool m_reversed = false; // a larger raw value shows a smaller number (reciprocal scaling)
};

} // namespace DriveDesk
