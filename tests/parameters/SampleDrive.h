#pragma once

#include "parameters/DriveDescription.h"

#include <limits>

namespace DriveDesk::TestData {

inline constexpr qint32 kMin = std::numeric_limits<qint32>::min();
inline constexpr qint32 kMax = std::numeric_limits<qint32>::max();

inline ParameterDescription parameter(quint16 address, const QString &name)
{
    ParameterDescription p;
    p.address = address;
    p.name = name;
    p.scaling = { address, 1, 1, 0, 0 };
    p.plaintextIndices.address = address;
    return p;
}

// Every field of a DriveDescription set to something other than its default.
inline DriveDescription sample()
{
    DriveDescription drive;
    drive.protocol = QStringLiteral("hsp5");
    drive.connection = QStringLiteral("/dev/ttyUSB0 38400 8E1");
    drive.driveAddress = 1;
    drive.language = 1;
    drive.identification = QStringLiteral("Simulated F5\nfirmware 1.2 \"test\"");
    drive.incompleteReason = QStringLiteral("cancelled by the user");

    GroupDescription sy;
    sy.address = 0x0000;
    sy.index = 0;
    sy.id = QStringLiteral("Sy");
    sy.shortcut = 's';
    sy.properties = 0x001F;
    sy.highestNumber = 50;
    sy.parameterCount = 3;
    sy.name = QStringLiteral("System");
    ParameterDescription bus = parameter(0x0007, QStringLiteral("Baud rate ext. bus"));
    bus.minimum = 0;
    bus.maximum = 6;
    bus.defaultValue = 3;
    bus.properties2 = 0x0F;
    bus.values[0] = 3;
    sy.parameters << bus;
    ParameterDescription odd = parameter(0x0009, QStringLiteral("values in other sets"));
    odd.values[3] = 9; // not set-programmable, yet the description holds a set-3 value
    odd.scaling.address = 0; // service 5 not answered for this address
    odd.plaintextIndices.address = 0x1234;
    sy.parameters << odd;
    sy.parameters << parameter(0x000A, QStringLiteral("nothing read")); // values all unknown

    GroupDescription ru;
    ru.address = 0x0200;
    ru.index = 1;
    ru.id = QStringLiteral("ru");
    ru.shortcut = char(0xE4); // Latin-1 'ä'
    ru.properties = 0xFFFF;
    ru.highestNumber = 255;
    ru.parameterCount = 256;
    ru.name = QStringLiteral("Anzeigeparameter ÄÖÜß");
    ParameterDescription state = parameter(0x0200, QStringLiteral("Zustand ä|\"x\""));
    state.minimum = kMin;
    state.maximum = kMax;
    state.defaultValue = -1;
    state.properties1 = 0xFFFFFFFF; // set-programmable among everything else
    state.properties2 = 0x80000008;
    state.scaling = { 0x0200, -3, 32767, -32768, 0xFFFF };
    state.plaintextIndices = { 0x0200, 5, 7, 2, 3 };
    state.plaintexts = {
        { 0x0001,
          QStringLiteral("Controller release"),
          { { 0x1, 1, QStringLiteral("released") } } },
        { 0x0006,
          QStringLiteral("Direction"),
          { { 0x0, 0, QStringLiteral("stop") },
            { 0x2, 2, QStringLiteral("forward") },
            { 0x4, 3, QStringLiteral("reverse") } } },
        { 0x0008, QStringLiteral("Brake"), { { 0x8, 0, QStringLiteral("brake open") } } },
        { 0xFFFFFFFF, QString(), {} },
    };
    state.values = { 1, std::nullopt, -5, kMin, kMax, 0, std::nullopt, 7 };
    state.error = QStringLiteral("set 1: data invalid");
    ru.parameters << state;
    ParameterDescription hz = parameter(0x0203, QStringLiteral("Actual frequency"));
    hz.scaling.divisor = 80;
    hz.scaling.flags = quint16(18 | (2 << 8));
    hz.properties1 = 1u << 11;
    hz.values = { -4180, 0, 1, 2, 3, 4, 5, 6 };
    ru.parameters << hz;

    GroupDescription fb;
    fb.address = 0x0280; // half-page operator group
    fb.index = 2;
    fb.id = QStringLiteral("Fb");
    fb.name = QStringLiteral("Fieldbus");
    fb.parameters << parameter(0x0289, QStringLiteral("Fb.09"));

    drive.groups << sy << ru << fb;
    return drive;
}

} // namespace DriveDesk::TestData
