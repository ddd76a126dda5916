#include "Codec.h"


namespace DriveDesk {

Ack DecodeError::answer() const
{
    switch (kind) {
    case Kind::ChecksumMismatch: return Ack::BccError;
    case Kind::Framing: return Ack::FramingError;
    case Kind::UnknownService: return Ack::ServiceNotAvailable;
    case Kind::UnexpectedByte: break;
    }
    return Ack::Ok;
}

QString decodeErrorKindName(DecodeError::Kind kind)
{
    switch (kind) {
    case DecodeError::Kind::ChecksumMismatch: return QStringLiteral("wrong BCC");
    case DecodeError::Kind::Framing: return QStringLiteral("framing error");
    case DecodeError::Kind::UnknownService: return QStringLiteral("unknown service");
    case DecodeError::Kind::UnexpectedByte: return QStringLiteral("unexpected bytes");
    }
    return QString();
}

QString protocolName(Protocol protocol)
{
    switch (protocol) {
    case Protocol::Hsp5: return QStringLiteral("hsp5");
    case Protocol::Din66019II: return QStringLiteral("din66019ii");
    case Protocol::Din66019: return QStringLiteral("din66019");
    }
    return QString();
}

std::optional<Protocol> protocolFromName(const QString &name)
{
    const QString n = name.trimmed().toLower();
    for (Protocol p : {Protocol::Hsp5, Protocol::Din66019II, Protocol::Din66019}) {
        if (n == protocolName(p))
            return p;
    }
    return std::nullopt;
}

} // namespace DriveDesk
