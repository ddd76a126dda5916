#pragma once

#include "parameters/DriveDescription.h"

// A drive description made by hand, with parameters of every kind the editor meets: what the
// format test and the Widgets tests of the model, filter and delegate read.
namespace DriveDesk::EditorSample {

// Units and representations of the display flags (seed 002 2.7.1).
inline constexpr quint16 kSeconds = 9;
inline constexpr quint16 kHz = 18;
inline quint16 flags(quint16 unit, int representation)
{
    return quint16(unit | (representation << 8));
}

// Properties 1: read level bits 0-2, write level bits 3-5, set-programmable bit 11.
inline quint32 levels(int read, int write, bool setProgrammable = false)
{
    return quint32(read) | quint32(write) << 3 | (setProgrammable ? 1u << 11 : 0u);
}
inline constexpr quint32 kWritable = 0x0F; // properties 2: visible and writable everywhere
inline constexpr quint32 kReadOnly = 0x05; // properties 2: visible, not writable

inline constexpr quint16 kState = 0x0200; // ru.00, read-only enumeration
inline constexpr quint16 kFrequency = 0x0203; // ru.03, read-only, 1/80 Hz
inline constexpr quint16 kMaxFrequency = 0x030A; // oP.10, set-programmable, 0.01 Hz
inline constexpr quint16 kRampTime = 0x030B; // oP.11, one value, 0.01 s
inline constexpr quint16 kSource = 0x030C; // oP.12, enumeration, "limited" above maximum
inline constexpr quint16 kControl = 0x0405; // Pn.05, bit-field of two definitions
inline constexpr quint16 kErrorMask = 0x0406; // Pn.06, hexadecimal
inline constexpr quint16 kService = 0x0407; // Pn.07, needs CP service to read

inline ParameterDescription parameter(quint16 address, const QString &name, quint32 properties1,
                                      quint32 properties2)
{
    ParameterDescription p;
    p.address = address;
    p.name = name;
    p.properties1 = properties1;
    p.properties2 = properties2;
    p.scaling = { address, 1, 1, 0, 0 };
    p.plaintextIndices.address = address;
    return p;
}

inline PlaintextEntry text(qint32 value, const QString &text)
{
    return { value, 0, text };
}

// Three groups with parameters of every kind the editor meets, and an empty group.
inline DriveDescription drive()
{
    DriveDescription drive;
    drive.protocol = QStringLiteral("hsp5");
    drive.driveAddress = 1;

    GroupDescription ru;
    ru.address = 0x0200;
    ru.index = 1;
    ru.id = QStringLiteral("ru");
    ru.name = QStringLiteral("Run display");
    ParameterDescription state
        = parameter(kState, QStringLiteral("Inverter state"), levels(0, 7), kReadOnly);
    state.maximum = 128;
    state.plaintexts = { { 0,
                           QString(),
                           { text(0, QStringLiteral("noP")), text(64, QStringLiteral("Facc")),
                             text(66, QStringLiteral("Fcon")) } } };
    state.values[0] = 66;
    ParameterDescription frequency
        = parameter(kFrequency, QStringLiteral("Actual frequency"), levels(0, 0), kReadOnly);
    frequency.scaling = { kFrequency, 80, 1, 0, flags(kHz, 2) };
    frequency.minimum = -32000;
    frequency.maximum = 32000;
    frequency.values[0] = -4180;
    ru.parameters << state << frequency;

    GroupDescription op;
    op.address = 0x0300;
    op.index = 2;
    op.id = QStringLiteral("oP");
    op.name = QStringLiteral("Operator");
    ParameterDescription maxFrequency
        = parameter(kMaxFrequency, QStringLiteral("Max. frequency"), levels(0, 1, true), kWritable);
    maxFrequency.scaling = { kMaxFrequency, 100, 1, 0, flags(kHz, 2) };
    maxFrequency.maximum = 40000;
    maxFrequency.defaultValue = 5000;
    maxFrequency.values = { 5000, 6000, 5000, 5000, 5000, 5000, 5000, 5000 };
    ParameterDescription ramp
        = parameter(kRampTime, QStringLiteral("Acceleration time"), levels(0, 1), kWritable);
    ramp.scaling = { kRampTime, 100, 1, 0, flags(kSeconds, 2) };
    ramp.maximum = 30000;
    ramp.defaultValue = 500;
    ramp.values[0] = 500;
    ParameterDescription source
        = parameter(kSource, QStringLiteral("Set value source"), levels(0, 1), kWritable);
    source.maximum = 2;
    source.plaintexts
        = { { 0x0003,
              QStringLiteral("Source"),
              { text(0, QStringLiteral("digital")), text(1, QStringLiteral("analog")),
                text(2, QStringLiteral("bus")), text(3, QStringLiteral("limited")) } } };
    source.values[0] = 1;
    op.parameters << maxFrequency << ramp << source;

    GroupDescription pn;
    pn.address = 0x0400;
    pn.index = 3;
    pn.id = QStringLiteral("Pn");
    pn.name = QStringLiteral("Protection");
    ParameterDescription control
        = parameter(kControl, QStringLiteral("Control word"), levels(0, 1), kWritable);
    control.maximum = 0x7FFF;
    control.plaintexts = {
        { 0x0003,
          QStringLiteral("Direction"),
          { text(0, QStringLiteral("stop")), text(1, QStringLiteral("forward")),
            text(2, QStringLiteral("reverse")) } },
        { 0x0004,
          QStringLiteral("Release"),
          { text(0, QStringLiteral("locked")), text(4, QStringLiteral("released")) } },
    };
    control.values[0] = 0x0005;
    ParameterDescription errorMask
        = parameter(kErrorMask, QStringLiteral("Error mask"), levels(0, 1), kWritable);
    errorMask.scaling = { kErrorMask, 1, 1, 0, flags(0, 6) };
    errorMask.maximum = 0x0FFF;
    errorMask.defaultValue = 0x00FF;
    errorMask.values[0] = 0x00FF;
    ParameterDescription service
        = parameter(kService, QStringLiteral("Service setting"), levels(2, 3), kWritable);
    service.maximum = 100;
    service.values[0] = 10;
    service.defaultValue = 10;
    pn.parameters << control << errorMask << service;

    GroupDescription dr;
    dr.address = 0x0500;
    dr.index = 4;
    dr.id = QStringLiteral("dr");
    dr.name = QStringLiteral("Motor data");

    drive.groups << ru << op << pn << dr;
    return drive;
}

} // namespace DriveDesk::EditorSample
