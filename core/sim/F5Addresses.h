#pragma once

#include <QtGlobal>

#include <array>

// Bus addresses of the parameters the simulated drive's behaviour hangs on (group page << 8 |
// number, keb_f5_notes.md). The data files define them; the drive reads and writes them here.
namespace DriveDesk::Sim::F5 {

constexpr quint16 kDriveAddress = 0x0006; // Sy.06
constexpr quint16 kControlWordHigh = 0x0029; // Sy.41
constexpr quint16 kControlWordLow = 0x0032; // Sy.50
// Read channels 1..4 (process data in, scope): Sy.16/18/20/22 address, Sy.17/19/21/23 set mask.
constexpr std::array<quint16, 4> kReadChannel { 0x0010, 0x0012, 0x0014, 0x0016 };
// Write channels 1..4 (process data out): Sy.24/26/28/30 address, Sy.25/27/29/31 set mask.
constexpr std::array<quint16, 4> kWriteChannel { 0x0018, 0x001A, 0x001C, 0x001E };

constexpr quint16 kSoftwareVersion = 0x0E06; // In.06, 0.01
// What identifies a drive (DriveIdentity): Sy.02 inverter identifier, Sy.03 power unit, In.00
// type, In.01 rated current, In.04 voltage class, In.06/In.07 software, In.10 serial number.
constexpr std::array<quint16, 8> kIdentification { 0x0002, 0x0003, 0x0E00, 0x0E01,
                                                   0x0E04, 0x0E06, 0x0E07, 0x0E0A };

constexpr quint16 kSetValueSource = 0x0301; // op.01: 0 op.03, 1 demo cycle
constexpr quint16 kCommandSpeed = 0x0303; // op.03, rpm
constexpr quint16 kDemoSpeed = 0x0304; // op.04, rpm
constexpr quint16 kDemoPeriod = 0x0305; // op.05, 0.1 s
constexpr quint16 kMinimumSpeedForward = 0x030A; // op.10
constexpr quint16 kMaximumSpeedForward = 0x030B; // op.11
constexpr quint16 kMinimumSpeedReverse = 0x030C; // op.12
constexpr quint16 kMaximumSpeedReverse = 0x030D; // op.13
constexpr quint16 kFixedSpeed1 = 0x0314; // op.20, rpm
constexpr quint16 kAccelerationTime = 0x031C; // op.28, 0.01 s per 100 Hz
constexpr quint16 kDecelerationTime = 0x031E; // op.30, 0.01 s per 100 Hz
constexpr quint16 kQuickStopTime = 0x0323; // op.35, 0.01 s per 100 Hz

constexpr quint16 kBoost = 0x0500; // uF.00, 0.1 %
constexpr quint16 kCornerFrequency = 0x0501; // uF.01, 0.1 Hz
constexpr quint16 kCornerVoltage = 0x0502; // uF.02, V

constexpr quint16 kRatedSpeed = 0x0601; // dr.01, rpm
constexpr quint16 kRatedCurrent = 0x0602; // dr.02, 0.1 A
constexpr quint16 kRatedFrequency = 0x0605; // dr.05, 0.1 Hz
constexpr quint16 kRatedTorque = 0x0609; // dr.09, 0.1 Nm
constexpr quint16 kPolePairs = 0x060A; // dr.10
constexpr quint16 kMagnetisingCurrent = 0x060C; // dr.12, 0.1 A

constexpr quint16 kActiveSet = 0x0902; // Fr.02
constexpr quint16 kSetPointer = 0x0909; // Fr.09

constexpr quint16 kSoftwareInputs = 0x0B02; // di.02
constexpr std::array<quint16, 4> kOutputCondition { 0x0C00, 0x0C01, 0x0C02, 0x0C03 }; // do.00..03
constexpr quint16 kOutputInversion = 0x0C0A; // do.10
constexpr quint16 kEncoderPulses = 0x1001; // Ec.01

} // namespace DriveDesk::Sim::F5
