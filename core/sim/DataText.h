#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>

namespace DriveDesk::Sim {

// A number as the data files write it: "12.5" with `decimals` = 2 gives 1250; hex with `hex`
// or an h suffix ("7FFFh", "-1"). Nothing for text that is not a number or does not fit 32 bits.
std::optional<qint32> parseNumber(const QString &text, int decimals = 0, bool hex = false);

// Whether the text reads as a decimal number ("-1", "130.0"); "7FFF" and "7FFFh" do not.
bool isDecimalNumber(const QString &text);

// A name or plaintext for the 7-bit line: at most 24 printable ASCII characters. Anything else
// is reported as a problem naming `what`, and the text is cut to 24 characters.
QByteArray lineText(const QString &text, const QString &what, QStringList &problems);

} // namespace DriveDesk::Sim
