#pragma once

#include "protocol/Codec.h"
#include "protocol/Language.h"

#include <QList>
#include <QSerialPort>
#include <QString>

#include <optional>

namespace DriveDesk {

// How the simulated drive behaves when DriveDesk runs it in process or drivedesk-sim serves it.
struct SimulationOptions {
    QList<int> driveAddresses{1}; // DIN66019(II): several drives on one bus
    int replyLatencyUs = 1000;    // time from the end of a request to the start of its reply
    bool paced = false;           // send and receive at the configured baud rate
    // For pacing, and over a pty the rate the operator's port must be set to (a drive hears
    // nothing sent at another rate).
    qint32 baudRate = 38400;
    int parameterCount = 0;       // 0: the standard simulated F5; more pads it with generated ones
    // The drives at these addresses are of another kind (other software, more parameters) or
    // have no identification at all (not an F5); the others are standard F5s.
    QList<int> otherKindAddresses;
    QList<int> unidentifiedAddresses;
    // HSP5: the drive also knows DriveDesk's services 13, 14, 19-21 and 51-53. Off, it knows
    // exactly seed 000's services and loses step on any other, as a real drive does.
    bool hsp5Extensions = false;
    // Fault injection. Per byte: corrupt one bit, drop the byte. Per telegram: hold the reply
    // back by delayMs, answer busy (ack 6), send an unsolicited inverter request (HSP5).
    double corruptByteRate = 0;
    double dropByteRate = 0;
    // One bit flipped in a byte that arrives unflagged, as on a line without parity: only the
    // protocol's checksum stands between it and the decoder. Both directions.
    double flipByteRate = 0;
    double delayRate = 0;
    int delayMs = 50;
    double busyRate = 0;
    double unsolicitedRate = 0;
    quint32 seed = 1;
};

// Where and how to reach a drive, as the command line and the connection dialog give it.
struct ConnectionSettings {
    enum class Kind : quint8 { Simulated, Serial, Tcp };

    // What --address and --baud accept (seed 003: 240..255 select groups and all drives).
    static constexpr int kMaxDriveAddress = 239;
    static constexpr qint32 kMinimumBaudRate = 50;
    static constexpr qint32 kMaximumBaudRate = 4'000'000;

    Kind kind = Kind::Simulated;
    QString device;           // serial: /dev/ttyUSB0, COM3
    QString host;             // tcp
    quint16 port = 0;         // tcp
    Protocol protocol = Protocol::Hsp5;
    int driveAddress = 1;     // DIN66019(II): 0..239
    qint32 baudRate = 38400;
    // Serial: find the rate the drive talks at (BaudRateSearch) instead of using baudRate;
    // baudRate then holds the rate found once connected.
    bool automaticBaudRate = false;
    // Character format; unset means the protocol's default (8E1 HSP5, 7E1 DIN66019II).
    std::optional<QSerialPort::DataBits> dataBits;
    std::optional<QSerialPort::Parity> parity;
    std::optional<QSerialPort::StopBits> stopBits;
    Language language = Language::English;
    // HSP5: the drive is known to have DriveDesk's services 13, 14, 19-21 and 51-53, so they
    // may be sent. Off (the default), only seed 000's services go on the line.
    bool hsp5Extensions = false;
    SimulationOptions simulation; // Kind::Simulated only

    QSerialPort::DataBits effectiveDataBits() const;
    QSerialPort::Parity effectiveParity() const;
    QSerialPort::StopBits effectiveStopBits() const;

    // "tcp:HOST:PORT", "serial:DEVICE", "sim"; false and *error on anything else.
    bool parseTarget(const QString &target, QString *error);
    QString target() const;
    QString displayName() const;
};

} // namespace DriveDesk
