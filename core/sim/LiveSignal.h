#pragma once

#include <QString>

#include <optional>

namespace DriveDesk::Sim {

// A value the drive computes instead of storing: the motor, the terminals, timers. The data
// files name them (column `signal`); docs/simulated-drive.md says what each one shows.
enum class LiveSignal : quint8 {
    None,
    State, // ru.00 inverter state code
    SetFrequency, // 0.0125 Hz
    ActualFrequency, // 0.0125 Hz
    SetSpeed, // rpm
    ActualSpeed, // 0.125 rpm
    OutputVoltage, // V
    OutputPower, // 0.01 kW
    TorqueSet, // 0.1 Nm
    ActualTorque, // 0.1 Nm
    Load, // % of rated torque
    ApparentCurrent, // 0.1 A
    PeakCurrent, // 0.1 A, writable (reset)
    DcVoltage, // V
    PeakDcVoltage, // V, writable (reset)
    HeatSink, // degC + 40
    InputState, // terminal bits
    OutputState, // terminal bits
    Overload, // %
    LastError, // ru.00 code
    ScopeTimer, // 1 ms, wraps at 65535
    StatusHigh,
    StatusLow,
    StatusLong,
    ControlLong, // Sy.41 << 16 | Sy.50, writable
    Password, // -1..-8: the password level in force, takes passwords
    OperatingHours, // 0.1 h
    ModulationHours, // 0.1 h
    SerialNumber,
    EncoderPosition, // increments, 4 per line
};

// The signal a data file names ("actualFrequency"); nothing for an unknown name.
std::optional<LiveSignal> liveSignalFromName(const QString &name);

} // namespace DriveDesk::Sim
