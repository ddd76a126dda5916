#pragma once

#include "parameters/PasswordLevel.h"

#include <QDialog>

#include <optional>

class QDialogButtonBox;
class QLabel;
class QLineEdit;

namespace DriveDesk {

// Asks for a password for the drive, showing the password level in force. The number goes to
// the AccessController, which writes it to the password parameter.
class PasswordDialog : public QDialog
{
    Q_OBJECT
public:
    static constexpr int kHighestPassword = 9999; // ud.01's upper limit

    explicit PasswordDialog(QWidget *parent = nullptr);

    // Nothing: the level has not been read yet.
    void setLevel(std::optional<PasswordLevel> level);
    // The number typed; nothing while the field holds none.
    std::optional<int> password() const;

    void accept() override;

signals:
    void passwordEntered(int password); // on OK

private:
    void updateOk();

    QLabel *m_level = nullptr;
    QLineEdit *m_password = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace DriveDesk
