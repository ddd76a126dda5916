#include "Acknowledge.h"

#include <QCoreApplication>

#include <array>

namespace DriveDesk {

namespace {

// Seed 002, chapter 1.2 names each code in English and German; the German column is the
// catalogue's translation.
constexpr std::array<const char *, 16> kTexts{{
    QT_TRANSLATE_NOOP("Acknowledge", "OK"),
    QT_TRANSLATE_NOOP("Acknowledge", "not ready"),
    QT_TRANSLATE_NOOP("Acknowledge", "address or password invalid"),
    QT_TRANSLATE_NOOP("Acknowledge", "data invalid"),
    QT_TRANSLATE_NOOP("Acknowledge", "parameter write protected"),
    QT_TRANSLATE_NOOP("Acknowledge", "BCC error"),
    QT_TRANSLATE_NOOP("Acknowledge", "inverter busy"),
    QT_TRANSLATE_NOOP("Acknowledge", "service not available"),
    QT_TRANSLATE_NOOP("Acknowledge", "password invalid"),
    QT_TRANSLATE_NOOP("Acknowledge", "telegram framing error: wrong count of characters"),
    QT_TRANSLATE_NOOP("Acknowledge", "transmission error: overrun, framing or parity error"),
    QT_TRANSLATE_NOOP("Acknowledge", "set selection invalid"),
    QT_TRANSLATE_NOOP("Acknowledge", "language selection invalid"),
    QT_TRANSLATE_NOOP("Acknowledge", "address invalid"),
    QT_TRANSLATE_NOOP("Acknowledge", "operation not possible"),
    QT_TRANSLATE_NOOP("Acknowledge", "unknown acknowledge 15"),
}};

} // namespace

QString ackText(Ack ack)
{
    const auto index = static_cast<std::size_t>(ack) & 0x0F;
    return QCoreApplication::translate("Acknowledge", kTexts[index]);
}

bool isTransient(Ack ack)
{
    return ack == Ack::Busy || ack == Ack::BccError || ack == Ack::TransmissionError
           || ack == Ack::FramingError;
}

} // namespace DriveDesk
