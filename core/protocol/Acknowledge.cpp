#include "Acknowledge.h"

#include <array>

namespace DriveDesk {

namespace {

struct AckTexts {
    const char *english;
    const char *german;
};

// Seed 002, chapter 1.2 gives both columns.
constexpr std::array<AckTexts, 16> kTexts{{
    {"OK", "OK"},
    {"not ready", "nicht bereit"},
    {"address or password invalid", "Adresse oder Passwort ungültig"},
    {"data invalid", "Daten ungültig"},
    {"parameter write protected", "Parameter schreibgeschützt"},
    {"BCC error", "BCC-Fehler"},
    {"inverter busy", "Umrichter beschäftigt"},
    {"service not available", "Dienst nicht verfügbar"},
    {"password invalid", "Passwort ungültig"},
    {"telegram framing error: wrong count of characters",
     "Telegramm-Rahmenfehler: falsche Zeichenanzahl"},
    {"transmission error: overrun, framing or parity error",
     "Übertragungsfehler: Überlauf-, Rahmen- oder Paritätsfehler"},
    {"set selection invalid", "Satzkennung ungültig"},
    {"language selection invalid", "Sprachkennung ungültig"},
    {"address invalid", "Adresse ungültig"},
    {"operation not possible", "Operation nicht möglich"},
    {"unknown acknowledge 15", "unbekannte Quittung 15"},
}};

} // namespace

QString ackText(Ack ack, Language language)
{
    const auto index = static_cast<std::size_t>(ack) & 0x0F;
    const AckTexts &texts = kTexts[index];
    return QString::fromUtf8(language == Language::German ? texts.german : texts.english);
}

bool isTransient(Ack ack)
{
    return ack == Ack::Busy || ack == Ack::BccError || ack == Ack::TransmissionError
           || ack == Ack::FramingError;
}

} // namespace DriveDesk
