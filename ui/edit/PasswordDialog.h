#pragma once

#include "parameters/PasswordLevel.h"

#include <QDialog>

#include <optional>

class QDialogButtonBox;
class QLabel;
class QLineEdit;

namespace DriveDesk {

// Asks for a password for the drive, showing the password level in force. OK hands the number
// on (passwordEntered) and waits for the drive: accepted closes the dialog, a refusal keeps it
// open with the drive's reason, so the user can try again without starting over.
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
    // Waiting for the drive's answer to the password entered.
    bool isChecking() const { return m_checking; }

    // The drive's answer: accepted closes the dialog; refused shows why and asks again.
    void passwordAccepted();
    void passwordRefused(const QString &reason);

    void accept() override;

signals:
    void passwordEntered(int password); // on OK; the dialog stays open until answered

private:
    void setChecking(bool checking);
    void updateOk();

    QLabel *m_level = nullptr;
    QLineEdit *m_password = nullptr;
    QLabel *m_answer = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    bool m_checking = false;
};

} // namespace DriveDesk
