#pragma once

#include <QString>

#include <array>
#include <optional>

namespace DriveDesk::Sim {

// The drive's 5-digit 7-segment display (service 8). One byte a digit: bit 0..6 = segments
// a..g, bit 7 = the decimal point. A '.' lights the point of the digit before it.
using SegmentPattern = std::array<quint8, 5>;

// The pattern of `text`, right-aligned like the drive's display; nothing when a character has
// no 7-segment glyph or the text needs more than five digits.
std::optional<SegmentPattern> sevenSegmentPattern(const QString &text);

// The text back from a pattern, with the glyphs this module writes ('?' for any other).
QString sevenSegmentText(const SegmentPattern &pattern);

} // namespace DriveDesk::Sim
