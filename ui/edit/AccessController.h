#pragma once

#include "parameters/PasswordLevel.h"

#include <QObject>

#include <optional>

namespace DriveDesk {

class DriveClient;
class DriveState;

// The drive's password level: read from the password parameter ud.01, which reads -1 - level,
// and changed by writing a password to it. The level in force is kept once, by the model, which
// locks the parameters above it in the view. Lives in the GUI thread; the client and the model
// outlive it.
class AccessController : public QObject
{
    Q_OBJECT
public:
    AccessController(DriveClient *client, DriveState *state, QObject *parent = nullptr);

    void readLevel(); // reads ud.01 (service 1, set 0), sets the model's level
    void enterPassword(int password); // writes ud.01, re-reads the level
    // The level last read; the model's (Supervisor: nothing locked) until then.
    PasswordLevel level() const;
    bool isLevelKnown() const { return m_known; }

signals:
    void levelChanged(DriveDesk::PasswordLevel level);
    // The level read rose above the one known before: what it opens can be read now.
    void levelRaised(DriveDesk::PasswordLevel from, DriveDesk::PasswordLevel to);
    // The drive's answer to enterPassword(): accepted, or refused with the reason in words.
    void passwordAnswered(bool accepted, const QString &reason);
    void message(const QString &text);

private:
    // Reads the level, after writing the password if one is given (core's PasswordLevelJob).
    void run(std::optional<qint32> password);
    // A value of ud.01 from the drive, read here or by a refresh.
    void takeReadValue(qint32 value);
    // The password parameter's value changed in the state (a refresh, a scan, polling).
    void passwordValueChanged(quint16 address);
    QString levelName(PasswordLevel level) const;

    DriveClient *m_client = nullptr;
    DriveState *m_state = nullptr;
    bool m_known = false; // the level was read from this drive
};

} // namespace DriveDesk
