#pragma once

#include "ValueEditor.h"

#include <QComboBox>

namespace DriveDesk {

// The texts of an enumeration (one plaintext definition) to choose from. Texts whose value lies
// outside the limits are shown but cannot be chosen; a starting value without a text is offered
// as it is, so that leaving the editor alone changes nothing.
class PlaintextComboBox : public QComboBox, public ValueEditor
{
    Q_OBJECT
public:
    explicit PlaintextComboBox(const ParameterFormat &format, QWidget *parent = nullptr);

signals:
    // The user picked a text from the list (a click, or Enter in the open list): write it.
    // Stepping the closed combo box with the keyboard or the wheel picks nothing yet.
    void picked();

protected:
    void setRawValue(qint32 raw) override;
    std::optional<qint32> editedValue(QString *problem) const override;
    void keyPressEvent(QKeyEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;

private:
    bool m_stepping = false;
};

} // namespace DriveDesk
