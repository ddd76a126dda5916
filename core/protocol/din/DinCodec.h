#pragma once

#include "protocol/Codec.h"

namespace DriveDesk {

// The ASCII protocols of seed 003 on a 7E1 multi-drop line: DIN66019II (services with invoke
// ids, plus the legacy telegrams on the same bus) or plain DIN66019 (legacy value telegrams and
// the status interrogation only). The decoders of both understand every form of the bus.
class DinCodec final : public ProtocolCodec
{
public:
    explicit DinCodec(Protocol protocol);

    Protocol protocol() const override { return m_protocol; }
    bool supports(Service service, Access access) const override;
    // Fields a telegram form does not carry (a read request's value, a response's drive
    // selection, the inverter invoke id) are ignored.
    QByteArray encode(const Telegram &telegram, QString *error = nullptr) const override;
    std::unique_ptr<FrameDecoder> makeDecoder(Role role) const override;
    int bitsPerCharacter() const override { return 10; } // 7E1

private:
    QByteArray encodeRequest(const Telegram &telegram, QString *error) const;
    QByteArray encodeResponse(const Telegram &telegram, QString *error) const;
    QByteArray encodeShortAnswer(const Telegram &telegram, QString *error) const;

    Protocol m_protocol = Protocol::Din66019II;
};

} // namespace DriveDesk
