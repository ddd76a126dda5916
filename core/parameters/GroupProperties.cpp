#include "GroupProperties.h"

namespace DriveDesk {

QStringList GroupProperties::describe(Language language) const
{
    const bool german = language == Language::German;
    QStringList lines;
    lines << (german ? QStringLiteral("Passwortlevel: %1") : QStringLiteral("password level: %1"))
                 .arg(passwordLevelName(passwordLevel(), language));
    if (isVisibleOnDisplay())
        lines << (german ? QStringLiteral("sichtbar auf der Anzeige")
                         : QStringLiteral("visible on the display"));
    if (isVisibleInCombivis())
        lines << (german ? QStringLiteral("sichtbar über COMBIVIS")
                         : QStringLiteral("visible in COMBIVIS"));
    for (int bit = 5; bit < 16; ++bit) {
        if (m_properties & (1u << bit)) {
            lines << (german ? QStringLiteral("freies Bit %1 gesetzt")
                             : QStringLiteral("free bit %1 set"))
                         .arg(bit);
        }
    }
    return lines;
}

} // namespace DriveDesk
