#pragma once

#include "Hsp5Layout.h"
#include "protocol/Codec.h"

namespace DriveDesk {

// The BCC that ends every HSP5 telegram: the XOR of all bytes before it.
quint8 hsp5Bcc(QByteArrayView bytes);

// KEB HSP5 (seed 000): binary telegrams without start or end character, whose length follows
// from the service byte. Byte 0 holds INV-ID-OP (high nibble) and INV-ID-FU (low nibble).
class Hsp5Codec final : public ProtocolCodec
{
public:
    explicit Hsp5Codec(Hsp5Services services = Hsp5Services::Seed)
        : m_services(services)
    {}

    Hsp5Services services() const { return m_services; }
    Protocol protocol() const override { return Protocol::Hsp5; }
    bool supports(Service service, Access access) const override;
    QByteArray encode(const Telegram &telegram, QString *error = nullptr) const override;
    std::unique_ptr<FrameDecoder> makeDecoder(Role role) const override;
    int bitsPerCharacter() const override { return 11; } // 8E1

private:
    Hsp5Services m_services;
};

} // namespace DriveDesk
