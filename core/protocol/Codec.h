#pragma once

#include "Telegram.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <memory>
#include <optional>
#include <variant>

namespace DriveDesk {

enum class Protocol : quint8 {
    Hsp5,       // binary, full duplex, point to point (seed 000)
    Din66019II, // ASCII, multi-drop, services with invoke ids (seed 003)
    Din66019,   // ASCII, the legacy telegrams (service -1) of the same bus
};

// Which side of the link a decoder sits on: the operator decodes responses (and requests the
// inverter starts, HSP5), the drive decodes requests.
enum class Role : quint8 { Operator, Drive };

// A stretch of the byte stream that is not a valid telegram. Never accepted as data.
struct DecodeError {
    enum class Kind : quint8 {
        ChecksumMismatch, // BCC wrong
        Framing,          // wrong count of characters / field layout
        UnknownService,   // service number the protocol does not define
        UnexpectedByte,   // garbage between telegrams, skipped
    };
    Kind kind = Kind::UnexpectedByte;
    QByteArray bytes;        // what was dropped
    QString detail;          // human-readable, names what was wrong
    quint8 operatorInvoke = 0; // the invoke id, where it could still be read (0 = unknown)
    int driveAddress = -1;   // DIN: selection in force for the broken request, if any

    // The acknowledge a drive answers this with (5, 9, 7), or Ok where it stays silent.
    Ack answer() const;
    bool operator==(const DecodeError &) const = default;
};

QString decodeErrorKindName(DecodeError::Kind kind);

using Decoded = std::variant<Telegram, DecodeError>;

// Streaming framer + field decoder: bytes in, telegrams or typed errors out. Pure: no I/O, no
// timers. Any split of the stream gives the same result; garbage is skipped and resynchronised.
class FrameDecoder
{
public:
    virtual ~FrameDecoder() = default;
    virtual void feed(QByteArrayView bytes) = 0;
    // The next complete item, or nothing until more bytes arrive.
    virtual std::optional<Decoded> next() = 0;
    // Drop a partial telegram, e.g. after an idle gap on the line or a lost link.
    virtual void reset() = 0;
    virtual qsizetype buffered() const = 0;
};

class ProtocolCodec
{
public:
    virtual ~ProtocolCodec() = default;
    virtual Protocol protocol() const = 0;
    // Whether the protocol defines this service in that access mode.
    virtual bool supports(Service service, Access access) const = 0;
    // Encodes a request or a response. Returns an empty array and sets *error when the
    // telegram cannot be expressed (unsupported service, text too long, value out of range).
    virtual QByteArray encode(const Telegram &telegram, QString *error = nullptr) const = 0;
    virtual std::unique_ptr<FrameDecoder> makeDecoder(Role role) const = 0;
    // Bits on the line per character (start + data + parity + stop): 11 for 8E1, 10 for 7E1.
    virtual int bitsPerCharacter() const = 0;
};

// How a codec is set up beyond its protocol.
struct CodecOptions {
    // HSP5: frame DriveDesk's layouts of services 13, 14, 19-21 and 51-53 too. Off, the codec
    // knows exactly seed 000's services, as every drive does (docs/protocol-hsp5.md).
    bool hsp5Extensions = false;
};

// In drivedesk_codecs.
std::unique_ptr<ProtocolCodec> makeCodec(Protocol protocol, CodecOptions options = {});

QString protocolName(Protocol protocol);                 // "hsp5", "din66019ii", "din66019"
std::optional<Protocol> protocolFromName(const QString &name);

} // namespace DriveDesk
