#pragma once

#include "ParameterDatabase.h"

#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk::Sim {

// The letters of the data files' `flags` column.
struct ParameterFlags
{
    bool readOnly = false; // r
    bool setProgrammable = false; // s
    bool keypadReadOnly = false; // k: writable over the bus only
    bool enter = false; // e: ENTER parameter
    bool hex = false; // h: hexadecimal display
    bool noProcessData = false; // n: not permitted as process data / scope channel
    bool excluded = false; // x: excluded from the complete parameter list
    bool plaintextOnly = false; // d: decimal value of plaintexts suppressed
    bool writeAlways = false; // a: a download writes it whatever the drive holds
    bool writeOnly = false; // o: an upload does not read it, a download writes it
    bool listReadOnly = false; // l: read only for up/download lists (writable otherwise)
};

// The flags `letters` name; nothing, with the offending letter in *bad, for an unknown one.
std::optional<ParameterFlags> parseFlags(const QString &letters, QChar *bad = nullptr);

// The unit code of the display flags (seed 002 2.7.1) for a data file's unit ("Hz", "rpm",
// "degC", "hex" = none); nothing for an unknown unit.
std::optional<int> unitCode(const QString &unit);

// What the data says about one parameter, before it becomes the drive's description.
struct ParameterSpec
{
    quint16 address = 0;
    QString id; // "ru.03", for messages
    QString nameEn;
    QString nameDe;
    QString unit;
    qint32 minimum = 0;
    qint32 maximum = 0;
    qint32 defaultValue = 0;
    int decimals = 0;
    bool explicitScale = false; // divisor/multiplier/offset given instead of 10^decimals
    qint16 divisor = 1;
    qint16 multiplier = 1;
    qint16 offset = 0;
    ParameterFlags flags;
    int readLevel = 3; // Application
    int writeLevel = 3;
    int enumeration = -1;
    LiveSignal signal = LiveSignal::None;
    QList<qint32> initial; // empty: the default; one value; or one per set
    bool systemParameter = false;
    bool encoderParameter = false;
};

// The drive's description of the parameter: properties 1/2 (seed 002 2.6) and display scaling
// (2.7) follow from the spec. Problems (a name too long or not ASCII, a default outside the
// limits) name the parameter; the name is then cut to 24 characters.
SimParameter buildParameter(const ParameterSpec &spec, QStringList &problems);

} // namespace DriveDesk::Sim
