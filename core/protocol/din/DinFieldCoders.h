#pragma once

#include "DinCharacters.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <type_traits>

// The three ways DinFields.cpp walks a service layout: writing the characters, counting how
// many a telegram must have, and reading them back. Each field call names the field, so that
// an error can say which one was wrong. Only DinFields.cpp includes this.

namespace DriveDesk {

inline constexpr int DinMaxTextLength = 24; // seed 002: names and plaintexts
inline constexpr int DinMaxFieldbusBytes = 64; // seed 002, service 13

inline QString dinFieldLabel(const char *name)
{
    return QLatin1String(name);
}

// Appends the fields as upper-case hex and text characters; keeps the first value that does
// not fit its field.
class DinFieldWriter
{
public:
    template<typename T> void hex(const char *name, T &value, int digits)
    {
        if (!m_error.isEmpty())
            return;
        const int bits = digits * 4;
        const qint64 number = qint64(value);
        const qint64 top = (qint64(1) << bits) - 1;
        const qint64 bottom = std::is_signed_v<T> ? -(qint64(1) << (bits - 1)) : 0;
        if (number < bottom || number > top) {
            m_error = QStringLiteral("%1 %2 does not fit %3 hex digits")
                          .arg(dinFieldLabel(name))
                          .arg(number)
                          .arg(digits);
            return;
        }
        const auto raw = quint64(number) & quint64(top);
        for (int shift = bits - 4; shift >= 0; shift -= 4)
            m_out.append(dinHexDigit(int(raw >> shift)));
    }

    template<typename C> void character(const char *name, C &c)
    {
        if (!m_error.isEmpty())
            return;
        if (!isDinTextCharacter(char(c))) {
            m_error = QStringLiteral("%1: character %2 is outside 20h..7Eh")
                          .arg(dinFieldLabel(name), dinCharacterName(char(c)));
            return;
        }
        m_out.append(char(c));
    }

    void text(const char *name, QByteArray &text)
    {
        if (text.size() > DinMaxTextLength) {
            fail(QStringLiteral("%1 of %2 characters, at most %3")
                     .arg(dinFieldLabel(name))
                     .arg(text.size())
                     .arg(DinMaxTextLength));
            return;
        }
        auto length = quint8(text.size());
        hex("text length", length, 2);
        for (char &c : text)
            character(name, c);
    }

    void bytes(const char *name, QByteArray &data)
    {
        if (data.size() > DinMaxFieldbusBytes) {
            fail(QStringLiteral("%1 of %2 bytes, at most %3")
                     .arg(dinFieldLabel(name))
                     .arg(data.size())
                     .arg(DinMaxFieldbusBytes));
            return;
        }
        auto length = quint8(data.size());
        hex("data length", length, 2);
        for (const char byte : data) {
            auto value = quint8(byte);
            hex(name, value, 2);
        }
    }

    void fail(const QString &error)
    {
        if (m_error.isEmpty())
            m_error = error;
    }

    QByteArray m_out;
    QString m_error;
};

// Counts the characters a layout needs, reading text lengths from the characters themselves.
class DinFieldMeasure
{
public:
    explicit DinFieldMeasure(QByteArrayView characters)
        : m_in(characters)
    { }

    template<typename T> void hex(const char *, T &, int digits) { m_size += digits; }
    template<typename C> void character(const char *, C &) { ++m_size; }
    void text(const char *, QByteArray &) { m_size += 2 + peekLength(); }
    void bytes(const char *, QByteArray &) { m_size += 2 + 2 * peekLength(); }

    QByteArrayView m_in;
    qsizetype m_size = 0;
    bool m_known = true; // false once a length field could not be read

private:
    int peekLength()
    {
        if (m_size + 2 > m_in.size()) {
            m_known = false;
            return 0;
        }
        const int high = dinHexValue(m_in[m_size]);
        const int low = dinHexValue(m_in[m_size + 1]);
        if (high < 0 || low < 0) {
            m_known = false;
            return 0;
        }
        return high * 16 + low;
    }
};

// Reads the fields back; keeps the first character that does not belong where it stands.
class DinFieldReader
{
public:
    explicit DinFieldReader(QByteArrayView characters)
        : m_in(characters)
    { }

    template<typename T> void hex(const char *name, T &value, int digits)
    {
        if (!available(digits))
            return;
        quint64 raw = 0;
        for (int i = 0; i < digits; ++i) {
            const char c = m_in[m_pos + i];
            const int digit = dinHexValue(c);
            if (digit < 0) {
                fail(badDigit(name, c));
                return;
            }
            raw = raw << 4 | quint64(digit);
        }
        m_pos += digits;
        if constexpr (std::is_signed_v<T>) {
            const quint64 sign = quint64(1) << (digits * 4 - 1);
            value = T(qint64(raw ^ sign) - qint64(sign)); // two's complement of the field width
        } else {
            value = T(raw);
        }
    }

    template<typename C> void character(const char *name, C &c)
    {
        if (!available(1))
            return;
        const char read = m_in[m_pos];
        if (!isDinTextCharacter(read)) {
            fail(QStringLiteral("%1: character %2 is outside 20h..7Eh")
                     .arg(dinFieldLabel(name), dinCharacterName(read)));
            return;
        }
        c = C(read);
        ++m_pos;
    }

    void text(const char *name, QByteArray &text)
    {
        quint8 length = 0;
        hex("text length", length, 2);
        if (!m_error.isEmpty())
            return;
        if (length > DinMaxTextLength) {
            fail(QStringLiteral("text length %1, at most %2").arg(length).arg(DinMaxTextLength));
            return;
        }
        QByteArray read(length, Qt::Uninitialized);
        for (char &c : read)
            character(name, c);
        if (m_error.isEmpty())
            text = read;
    }

    void bytes(const char *name, QByteArray &data)
    {
        quint8 length = 0;
        hex("data length", length, 2);
        if (!m_error.isEmpty())
            return;
        if (length > DinMaxFieldbusBytes) {
            fail(QStringLiteral("data length %1, at most %2").arg(length).arg(DinMaxFieldbusBytes));
            return;
        }
        QByteArray read(length, Qt::Uninitialized);
        for (char &byte : read) {
            quint8 value = 0;
            hex(name, value, 2);
            byte = char(value);
        }
        if (m_error.isEmpty())
            data = read;
    }

    void fail(const QString &error)
    {
        if (m_error.isEmpty())
            m_error = error;
    }

    QByteArrayView m_in;
    qsizetype m_pos = 0;
    QString m_error;

private:
    bool available(qsizetype count)
    {
        if (!m_error.isEmpty())
            return false;
        if (m_pos + count > m_in.size()) {
            fail(QStringLiteral("%1 data characters, too few for the fields").arg(m_in.size()));
            return false;
        }
        return true;
    }

    static QString badDigit(const char *name, char c)
    {
        if (c >= 'a' && c <= 'f')
            return QStringLiteral("%1: lower-case '%2', DIN66019II sends upper-case hex digits")
                .arg(dinFieldLabel(name), QString(QLatin1Char(c)));
        return QStringLiteral("%1: %2 is not a hex digit")
            .arg(dinFieldLabel(name), dinCharacterName(c));
    }
};

} // namespace DriveDesk
