#pragma once

#include <QString>

#include <optional>

namespace DriveDesk {

// The language id the services carry (names, plaintexts): 0 English, 1 German. The drive's own
// texts come in it; DriveDesk's texts follow the installed translator instead.
enum class Language : quint8 { English = 0, German = 1 };

// "en" and "de": how the command lines and the settings name a language.
inline QString languageCode(Language language)
{
    return language == Language::German ? QStringLiteral("de") : QStringLiteral("en");
}

// The language a code names (any case), or nothing.
inline std::optional<Language> languageFromCode(const QString &code)
{
    if (code.compare(QLatin1String("en"), Qt::CaseInsensitive) == 0)
        return Language::English;
    if (code.compare(QLatin1String("de"), Qt::CaseInsensitive) == 0)
        return Language::German;
    return std::nullopt;
}

} // namespace DriveDesk
