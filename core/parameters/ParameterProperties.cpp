#include "ParameterProperties.h"

#include <array>

namespace DriveDesk {

namespace {

struct Words
{
    const char *english;
    const char *german;
};

struct Flag
{
    int bit;
    Words words;
};

QString say(const Words &words, Language language)
{
    return QString::fromUtf8(language == Language::German ? words.german : words.english);
}

constexpr std::array<Words, 4> kWidths { {
    { "stored as byte", "gespeichert als Byte" },
    { "stored as word", "gespeichert als Wort" },
    { "stored as long", "gespeichert als Long" },
    { "storage width 3 (not used)", "Speicherbreite 3 (nicht genutzt)" },
} };

constexpr std::array<Words, 4> kScalingResults { {
    { "scaling result: byte", "Normierungsergebnis: Byte" },
    { "scaling result: word", "Normierungsergebnis: Wort" },
    { "scaling result: long", "Normierungsergebnis: Long" },
    { "scaling result: none", "Normierungsergebnis: keines" },
} };

constexpr std::array<Words, 4> kLimitTypes { {
    { "constant", "konstant" },
    { "variable at power on", "variabel bei Power On" },
    { "always variable", "immer variabel" },
    { "type 3 (not used)", "Typ 3 (nicht genutzt)" },
} };

constexpr std::array<Words, 4> kEnterModes { {
    { "no enter", "kein Enter" },
    { "enter with dot", "Enter mit Punkt" },
    { "enter without dot", "Enter ohne Punkt" },
    { "enter mode 3 (not used)", "Enter-Modus 3 (nicht genutzt)" },
} };

constexpr std::array<Words, 4> kFilterings { {
    { "no display filtering", "keine Beruhigung" },
    { "display filtering: time slot", "Anzeigeberuhigung: Zeitraster" },
    { "display filtering: filter", "Anzeigeberuhigung: Filter" },
    { "display filtering 3 (not used)", "Anzeigeberuhigung 3 (nicht genutzt)" },
} };

// Single bits of properties 1 worth naming when set (the fields are named separately).
constexpr std::array<Flag, 10> kFlags1 { {
    { 10, { "signed", "mit Vorzeichen" } },
    { 11, { "set-programmable", "satzprogrammierbar" } },
    { 16,
      { "writable while the active set is displayed",
        "schreibbar bei Anzeige des aktuellen Satzes" } },
    { 17, { "scaled in the background", "Normierung im Hintergrund" } },
    { 18, { "variable default value", "Defaultwert variabel" } },
    { 19, { "default loaded only for a new device", "Defaultwert nur bei neuem Gerät laden" } },
    { 28,
      { "not permitted as process data or for surveillance",
        "nicht als Prozessdatum oder Überwachungsparameter zugelassen" } },
    { 29, { "encoder parameter", "Encoder-Parameter" } },
    { 30, { "system parameter", "Systemparameter" } },
    { 31, { "variable display scaling", "variable Anzeigenormierung" } },
} };

constexpr std::array<Flag, 20> kFlags2 { {
    { 0, { "visible on the display", "sichtbar auf der Anzeige" } },
    { 1, { "writable on the display", "schreibbar auf der Anzeige" } },
    { 2, { "visible in COMBIVIS", "sichtbar über COMBIVIS" } },
    { 3, { "writable via COMBIVIS", "schreibbar über COMBIVIS" } },
    { 8, { "rotating count", "rotierende Zählweise" } },
    { 9, { "changed by the inverter", "wird vom Umrichter geändert" } },
    { 10, { "value without plaintext not displayed", "Wert ohne Klartext wird nicht angezeigt" } },
    { 11,
      { "configuration flag set (indirect configuration parameters, offline time base µs)",
        "Konfigurationsflag gesetzt (indirekt adressierte Konfiguration, Offline-Zeitbasis µs)" } },
    { 12,
      { "write always: written by upload and download",
        "Write Always: bei Up- und Download geschrieben" } },
    { 13,
      { "write only: not read by upload, written by download",
        "Write Only: beim Upload nicht gelesen, beim Download geschrieben" } },
    { 14,
      { "excluded from the complete parameter list", "nicht in der kompletten Parameterliste" } },
    { 15, { "not permitted as CP parameter", "nicht als CP-Parameter zugelassen" } },
    { 16, { "decimal value of plaintexts suppressed", "Dezimalwert des Klartextes unterdrückt" } },
    { 17,
      { "read-only for up/download lists: not written by download",
        "Read Only für Up-/Download-Listen: beim Download nicht geschrieben" } },
    { 18, { "protected", "geschützt" } },
    { 19, { "writable only at nop or error", "nur schreibbar bei nop oder Fehler" } },
    { 20,
      { "default not loaded while invisible", "Defaultwert bei Unsichtbarkeit nicht geladen" } },
    { 21, { "shows the state at 'NOP' and 'LS'", "zeigt bei 'NOP' und 'LS' den Status" } },
    { 22, { "indirectly addressed", "indirekt adressiert" } },
    { 23,
      { "not set-programmable for 'foc synchron'",
        "nicht satzprogrammierbar für 'foc synchron'" } },
} };

QString inverterTypes(quint32 bits)
{
    QStringList types;
    for (int type = 0; type < ParameterProperties::kInverterTypes; ++type) {
        if (bits & (1u << type))
            types << QString::number(type);
    }
    return types.join(QStringLiteral(", "));
}

} // namespace

bool ParameterProperties::isVisibleForInverterType(int type) const
{
    return type >= 0 && type < kInverterTypes && bit1(20 + type);
}

bool ParameterProperties::isWritableForInverterType(int type) const
{
    return type >= 0 && type < kInverterTypes && bit1(24 + type);
}

QStringList ParameterProperties::describe(Language language) const
{
    const bool german = language == Language::German;
    QStringList lines;
    lines << (german ? QStringLiteral("Passwortlevel Lesen: %1") : QStringLiteral("read level: %1"))
                 .arg(passwordLevelName(readLevel(), language));
    lines << (german ? QStringLiteral("Passwortlevel Schreiben: %1")
                     : QStringLiteral("write level: %1"))
                 .arg(passwordLevelName(writeLevel(), language));
    lines << say(kWidths[std::size_t(width())], language);
    lines << say(kScalingResults[std::size_t(scalingResult())], language);
    if (lowerLimitType() != LimitType::Constant) {
        lines << (german ? QStringLiteral("Untergrenze %1") : QStringLiteral("lower limit %1"))
                     .arg(say(kLimitTypes[std::size_t(lowerLimitType())], language));
    }
    if (upperLimitType() != LimitType::Constant) {
        lines << (german ? QStringLiteral("Obergrenze %1") : QStringLiteral("upper limit %1"))
                     .arg(say(kLimitTypes[std::size_t(upperLimitType())], language));
    }
    if (const quint32 visible = field1(20, 4)) {
        lines << (german ? QStringLiteral("sichtbar für Umrichtertyp %1")
                         : QStringLiteral("visible for inverter type %1"))
                     .arg(inverterTypes(visible));
    }
    if (const quint32 writable = field1(24, 4)) {
        lines << (german ? QStringLiteral("schreibbar für Umrichtertyp %1")
                         : QStringLiteral("writable for inverter type %1"))
                     .arg(inverterTypes(writable));
    }
    for (const Flag &flag : kFlags1) {
        if (bit1(flag.bit))
            lines << say(flag.words, language);
    }

    if (isReadOnly())
        lines << (german ? QStringLiteral("über COMBIVIS nur lesbar")
                         : QStringLiteral("read-only via COMBIVIS"));
    if (enterMode() != EnterMode::None)
        lines << say(kEnterModes[std::size_t(enterMode())], language);
    if (displayFiltering() != DisplayFiltering::None)
        lines << say(kFilterings[std::size_t(displayFiltering())], language);
    for (const Flag &flag : kFlags2) {
        if (bit2(flag.bit))
            lines << say(flag.words, language);
    }
    // The free bits are named too: a drive that sets them means something by it.
    for (int bit = 24; bit < 32; ++bit) {
        if (bit2(bit)) {
            lines << (german ? QStringLiteral("Eigenschaften 2: freies Bit %1 gesetzt")
                             : QStringLiteral("properties 2: free bit %1 set"))
                         .arg(bit);
        }
    }
    return lines;
}

} // namespace DriveDesk
