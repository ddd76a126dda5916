#pragma once

#include "parameters/DisplayScaling.h"
#include "parameters/DriveDescription.h"
#include "parameters/Plaintexts.h"

#include <QCoreApplication>

#include <optional>

namespace DriveDesk {

// How one parameter's raw values read in the table and in its editors, and how a typed text
// becomes a raw value again. The table and the editors both go through it, so they agree.
class ParameterFormat
{
    Q_DECLARE_TR_FUNCTIONS(ParameterFormat)
public:
    ParameterFormat() = default;
    explicit ParameterFormat(const ParameterDescription &parameter);

    // The same limits with identity scaling and no plaintexts: raw integers.
    ParameterFormat rawFormat() const;

    const DisplayScaling &scaling() const { return m_scaling; }
    const Plaintexts &plaintexts() const { return m_plaintexts; }
    qint32 minimum() const { return m_minimum; }
    qint32 maximum() const { return m_maximum; }
    bool isRaw() const { return m_raw; }
    // Several plaintext definitions with texts: one field per definition.
    bool isBitField() const { return m_plaintexts.isBitField(); }
    bool isHexadecimal() const;

    // What the drive shows: the plaintext where one fits, otherwise the scaled number. A
    // bit-field always reads as its fields, unexplained bits named.
    QString text(qint32 raw, bool withUnit = true) const;
    // The scaled number without plaintext, e.g. for limits.
    QString number(qint32 raw, bool withUnit = false) const;

    bool isWithinLimits(qint32 raw) const { return raw >= m_minimum && raw <= m_maximum; }
    // Why the value may not be written ("outside the limits 0.00 .. 400.00 Hz"); empty if it may.
    QString limitsProblem(qint32 raw) const;

    enum class Limits : quint8 { Check, Ignore };

    // A text as a user types it: a plaintext or a number, with or without the unit. Refused
    // with the reason when it is neither, when the nearest raw value would show differently
    // from what was typed (nothing is rounded away unseen) or when it lies outside the limits.
    std::optional<qint32> parse(const QString &text, QString *error = nullptr,
                                Limits limits = Limits::Check) const;

private:
    std::optional<qint32> parseNumber(const QString &text, QString *error) const;

    DisplayScaling m_scaling;
    Plaintexts m_plaintexts;
    qint32 m_minimum = 0;
    qint32 m_maximum = 0;
    bool m_raw = false;
};

} // namespace DriveDesk
