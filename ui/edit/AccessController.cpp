#include "AccessController.h"

#include "client/DriveClient.h"
#include "state/DriveState.h"
#include "session/PasswordLevelJob.h"

#include <QFutureWatcher>

namespace DriveDesk {

AccessController::AccessController(DriveClient *client, DriveState *state, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_state(state)
{
    // A refresh or a scan reading ud.01 tells the level as well.
    connect(m_state, &DriveState::cellsChanged, this, &AccessController::passwordValueChanged);
    connect(m_state, &DriveState::parameterChanged, this, &AccessController::passwordValueChanged);
    connect(m_state, &DriveState::reset, this, [this] {
        const std::optional<qint32> value = m_state->value(kPasswordParameterAddress, 0);
        if (value && passwordLevelFromReadValue(*value))
            takeReadValue(*value);
    });
}

PasswordLevel AccessController::level() const
{
    return m_state->passwordLevel();
}

void AccessController::readLevel()
{
    run(std::nullopt);
}

void AccessController::enterPassword(int password)
{
    run(password);
}

void AccessController::run(std::optional<qint32> password)
{
    auto *watcher = new QFutureWatcher<PasswordLevelOutcome>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, password] {
        watcher->deleteLater();
        const QFuture<PasswordLevelOutcome> future = watcher->future();
        if (future.isCanceled() || future.resultCount() == 0) {
            if (password)
                emit passwordAnswered(false, tr("the connection closed before the drive answered"));
            return;
        }
        const PasswordLevelOutcome outcome = future.result();
        if (password && !outcome.passwordAccepted) {
            emit message(tr("Password not accepted: %1").arg(outcome.error));
            emit passwordAnswered(false, outcome.error);
            return;
        }
        if (password) {
            emit message(tr("Password accepted"));
            emit passwordAnswered(true, QString());
        }
        if (!outcome.readValue) {
            emit message(tr("The password level could not be read: %1").arg(outcome.error));
            return;
        }
        m_state->setValue(kPasswordParameterAddress, 0, *outcome.readValue);
        takeReadValue(*outcome.readValue);
    });
    watcher->setFuture(m_client->run(
        std::make_shared<PasswordLevelJob>(m_client->settings().protocol, password)));
}

void AccessController::takeReadValue(qint32 value)
{
    const std::optional<PasswordLevel> level = passwordLevelFromReadValue(value);
    if (!level) {
        emit message(tr("The password parameter reads %1, which names no password level: the "
                        "level stays %2")
                         .arg(value)
                         .arg(levelName(this->level())));
        return;
    }
    const bool wasKnown = m_known;
    const PasswordLevel before = this->level();
    const bool changed = !m_known || *level != before;
    m_known = true;
    m_state->setPasswordLevel(*level);
    if (changed) {
        emit levelChanged(*level);
        emit message(tr("Password level: %1").arg(levelName(*level)));
    }
    // Before the first reading the values were read at whatever level the drive had.
    if (wasKnown && *level > before)
        emit levelRaised(before, *level);
}

void AccessController::passwordValueChanged(quint16 address)
{
    if (address != kPasswordParameterAddress)
        return;
    // A value that names no level is a password on its way, not a reading.
    const std::optional<qint32> value = m_state->value(kPasswordParameterAddress, 0);
    const std::optional<PasswordLevel> level
        = value ? passwordLevelFromReadValue(*value) : std::nullopt;
    if (level && (!m_known || *level != this->level()))
        takeReadValue(*value);
}

QString AccessController::levelName(PasswordLevel level) const
{
    return passwordLevelName(level);
}

} // namespace DriveDesk
