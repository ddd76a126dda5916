#include "PasswordLevel.h"

#include <QCoreApplication>

#include <array>

namespace DriveDesk {

namespace {

// The seed names the levels in English in both columns; the German words are the catalogue's.
constexpr std::array<const char *, 8> kNames { {
    QT_TRANSLATE_NOOP("PasswordLevel", "CP read only"),
    QT_TRANSLATE_NOOP("PasswordLevel", "CP read/write"),
    QT_TRANSLATE_NOOP("PasswordLevel", "CP service"),
    QT_TRANSLATE_NOOP("PasswordLevel", "Application"),
    QT_TRANSLATE_NOOP("PasswordLevel", "Drive mode"),
    QT_TRANSLATE_NOOP("PasswordLevel", "unused"),
    QT_TRANSLATE_NOOP("PasswordLevel", "Security"),
    QT_TRANSLATE_NOOP("PasswordLevel", "Supervisor"),
} };

} // namespace

QString passwordLevelName(PasswordLevel level)
{
    return QCoreApplication::translate("PasswordLevel", kNames[std::size_t(level) & 0x07]);
}

qint32 passwordReadValue(PasswordLevel level)
{
    return -1 - qint32(quint8(level) & 0x07);
}

std::optional<PasswordLevel> passwordLevelFromReadValue(qint32 value)
{
    if (value > -1 || value < -8)
        return std::nullopt;
    return PasswordLevel(-1 - value);
}

} // namespace DriveDesk
