#include "PasswordLevel.h"

#include <array>

namespace DriveDesk {

namespace {

struct LevelNames
{
    const char *english;
    const char *german;
};

// The seed names the levels in English in both columns; the German words are ours.
constexpr std::array<LevelNames, 8> kNames { {
    { "CP read only", "CP nur lesen" },
    { "CP read/write", "CP lesen/schreiben" },
    { "CP service", "CP Service" },
    { "Application", "Applikation" },
    { "Drive mode", "Drive-Mode" },
    { "unused", "nicht genutzt" },
    { "Security", "Security" },
    { "Supervisor", "Supervisor" },
} };

} // namespace

QString passwordLevelName(PasswordLevel level, Language language)
{
    const LevelNames &names = kNames[std::size_t(level) & 0x07];
    return QString::fromUtf8(language == Language::German ? names.german : names.english);
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
