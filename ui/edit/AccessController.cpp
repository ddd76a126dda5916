#include "AccessController.h"

#include "ReplyWatch.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"

namespace DriveDesk {

AccessController::AccessController(DriveClient *client, ParameterModel *model, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_model(model)
    , m_level(model->passwordLevel())
{
    // A refresh or a scan reading ud.01 tells the level as well.
    connect(m_model, &QAbstractItemModel::dataChanged, this, &AccessController::modelDataChanged);
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
        const std::optional<qint32> value = m_model->value(kPasswordAddress, 0);
        if (value && passwordLevelFromReadValue(*value))
            takeReadValue(*value);
    });
}

void AccessController::readLevel()
{
    whenReplied(this, m_client->readValueStandard(kPasswordAddress, 0), [this](const Reply &reply) {
        if (const auto *value = reply.data<ParameterValue>()) {
            m_model->setValue(kPasswordAddress, 0, value->value);
            takeReadValue(value->value);
            return;
        }
        emit message(tr("The password level could not be read: %1").arg(reply.message()));
    });
}

void AccessController::enterPassword(int password)
{
    whenReplied(this, m_client->writeValueStandard(kPasswordAddress, password, 0),
                [this](const Reply &reply) {
                    if (!reply.ok()) {
                        emit message(tr("Password not accepted: %1").arg(reply.message()));
                        return;
                    }
                    emit message(tr("Password accepted"));
                    readLevel();
                });
}

void AccessController::takeReadValue(qint32 value)
{
    const std::optional<PasswordLevel> level = passwordLevelFromReadValue(value);
    if (!level) {
        emit message(tr("The password parameter reads %1, which names no password level: the "
                        "level stays %2")
                         .arg(value)
                         .arg(levelName(m_level)));
        return;
    }
    const bool changed = !m_known || *level != m_level;
    m_known = true;
    m_level = *level;
    m_model->setPasswordLevel(*level);
    if (changed) {
        emit levelChanged(*level);
        emit message(tr("Password level: %1").arg(levelName(*level)));
    }
}

void AccessController::modelDataChanged(const QModelIndex &topLeft, const QModelIndex &bottomRight)
{
    const QModelIndex cell = m_model->valueIndex(kPasswordAddress, 0);
    if (!cell.isValid() || cell.parent() != topLeft.parent() || cell.row() < topLeft.row()
        || cell.row() > bottomRight.row() || cell.column() < topLeft.column()
        || cell.column() > bottomRight.column()) {
        return;
    }
    // A value that names no level is a password on its way, not a reading.
    const std::optional<qint32> value = m_model->value(kPasswordAddress, 0);
    const std::optional<PasswordLevel> level
        = value ? passwordLevelFromReadValue(*value) : std::nullopt;
    if (level && (!m_known || *level != m_level))
        takeReadValue(*value);
}

QString AccessController::levelName(PasswordLevel level) const
{
    return passwordLevelName(level);
}

} // namespace DriveDesk
