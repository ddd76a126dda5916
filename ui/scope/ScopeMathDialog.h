#pragma once

#include "scope/ScopeMathDefinition.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;

namespace DriveDesk {

// Asks for a math channel: its kind, the channel(s) it reads and a moving average's window.
// What is wrong with a choice is core's (ScopeMathDefinition::check()); OK waits until nothing
// is. Shown with open(), never exec().
class ScopeMathDialog : public QDialog
{
    Q_OBJECT
public:
    // `channels`: the recording's four channels' titles, in order.
    ScopeMathDialog(const QStringList &channels, QWidget *parent = nullptr);

    ScopeMathDefinition definition() const;
    void setDefinition(const ScopeMathDefinition &definition);

private:
    void checkChoice();

    QComboBox *m_kind = nullptr;
    QComboBox *m_first = nullptr;
    QComboBox *m_second = nullptr;
    QDoubleSpinBox *m_window = nullptr;
    QComboBox *m_windowUnit = nullptr;
    QLabel *m_problem = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace DriveDesk
