#include "SevenSegment.h"

#include <QList>

namespace DriveDesk::Sim {

namespace {

constexpr quint8 kPoint = 0x80;

struct Glyph
{
    char character;
    quint8 segments;
};

// Upper and lower case share a glyph where the display cannot tell them apart.
constexpr Glyph kGlyphs[] = {
    { ' ', 0x00 }, { '-', 0x40 }, { '_', 0x08 }, { '/', 0x52 }, { '0', 0x3F }, { '1', 0x06 },
    { '2', 0x5B }, { '3', 0x4F }, { '4', 0x66 }, { '5', 0x6D }, { '6', 0x7D }, { '7', 0x07 },
    { '8', 0x7F }, { '9', 0x6F }, { 'A', 0x77 }, { 'a', 0x77 }, { 'B', 0x7C }, { 'b', 0x7C },
    { 'C', 0x39 }, { 'c', 0x58 }, { 'D', 0x5E }, { 'd', 0x5E }, { 'E', 0x79 }, { 'e', 0x79 },
    { 'F', 0x71 }, { 'f', 0x71 }, { 'G', 0x3D }, { 'g', 0x3D }, { 'H', 0x76 }, { 'h', 0x74 },
    { 'I', 0x30 }, { 'i', 0x10 }, { 'J', 0x1E }, { 'j', 0x1E }, { 'K', 0x75 }, { 'k', 0x75 },
    { 'L', 0x38 }, { 'l', 0x38 }, { 'M', 0x37 }, { 'm', 0x37 }, { 'N', 0x37 }, { 'n', 0x54 },
    { 'O', 0x3F }, { 'o', 0x5C }, { 'P', 0x73 }, { 'p', 0x73 }, { 'Q', 0x67 }, { 'q', 0x67 },
    { 'R', 0x50 }, { 'r', 0x50 }, { 'S', 0x6D }, { 's', 0x6D }, { 'T', 0x78 }, { 't', 0x78 },
    { 'U', 0x3E }, { 'u', 0x1C }, { 'V', 0x3E }, { 'v', 0x1C }, { 'W', 0x3E }, { 'w', 0x1C },
    { 'X', 0x76 }, { 'x', 0x76 }, { 'Y', 0x6E }, { 'y', 0x6E }, { 'Z', 0x5B }, { 'z', 0x5B },
};

std::optional<quint8> glyph(QChar c)
{
    for (const Glyph &g : kGlyphs) {
        if (QLatin1Char(g.character) == c)
            return g.segments;
    }
    return std::nullopt;
}

} // namespace

std::optional<SegmentPattern> sevenSegmentPattern(const QString &text)
{
    QList<quint8> digits;
    for (const QChar c : text) {
        if (c == QLatin1Char('.')) {
            if (digits.isEmpty() || (digits.last() & kPoint))
                digits.append(kPoint);
            else
                digits.last() |= kPoint;
            continue;
        }
        const std::optional<quint8> segments = glyph(c);
        if (!segments)
            return std::nullopt;
        digits.append(*segments);
    }
    if (digits.size() > 5)
        return std::nullopt;
    SegmentPattern pattern {};
    const qsizetype offset = 5 - digits.size();
    for (qsizetype i = 0; i < digits.size(); ++i)
        pattern[std::size_t(offset + i)] = digits.at(i);
    return pattern;
}

QString sevenSegmentText(const SegmentPattern &pattern)
{
    QString text;
    for (quint8 digit : pattern) {
        const quint8 segments = digit & quint8(~kPoint);
        QChar c = QLatin1Char('?');
        for (const Glyph &g : kGlyphs) {
            if (g.segments == segments) {
                c = QLatin1Char(g.character);
                break;
            }
        }
        text += c;
        if (digit & kPoint)
            text += QLatin1Char('.');
    }
    return text.trimmed();
}

} // namespace DriveDesk::Sim
