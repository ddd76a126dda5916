#pragma once

#include <QString>
#include <QStringView>

#include <optional>

namespace DriveDesk {

// A decimal number as a user types it ("-12,50 Hz"): a sign, the digits before and after the
// separator ('.' or ','). The one place that says what a typed number looks like.
struct DecimalText {
    bool negative = false;
    QString integral;     // without leading zeros: empty for 0
    QString fraction;     // without trailing zeros
    qsizetype length = 0; // the characters of the text the number takes

    // The number at the start of `text`, or nothing when it does not start with one.
    static std::optional<DecimalText> read(const QString &text);
    // "-12.5": '.' as the separator, "0" for zero, no sign on zero.
    QString canonical() const;
};

} // namespace DriveDesk
