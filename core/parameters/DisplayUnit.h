#pragma once

#include <QString>

#include <optional>

namespace DriveDesk {

// The unit table of the display flags, bits 0-5 (seed 002 2.7.1).

constexpr int kDisplayUnitCount = 41; // codes 0 (none) .. 40 (s/h); 41-63 are not assigned

// "Hz" for 18, "µs" for 7; empty for 0 (no unit) and for codes the table does not assign.
QString displayUnitSymbol(int code);

// The code for a symbol as users type it: exact, then the ASCII spellings ("us", "rpm", "Ohm",
// "degC", "m/s2"), then case-insensitively ("hz"). Nothing for no unit or an unknown one.
std::optional<int> displayUnitFromSymbol(const QString &symbol);

// A number as shown with its unit ("7.50 s"), or alone when there is none.
QString withUnit(const QString &number, const QString &unit);

} // namespace DriveDesk
