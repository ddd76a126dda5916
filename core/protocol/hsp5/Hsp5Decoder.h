#pragma once

#include "Hsp5Layout.h"
#include "protocol/Codec.h"

namespace DriveDesk {

// Splits an HSP5 byte stream into telegrams and typed errors. Pure: bytes in, items out.
//
// A telegram has no start character, so the decoder keeps step by lengths. In step (at the
// start and after each good telegram) the bytes at hand are trusted to start a telegram: its
// first failure is reported with its kind (ChecksumMismatch, UnknownService, Framing) and one
// byte is dropped. Out of step, every byte that starts no good telegram joins one
// UnexpectedByte error, reported when the next good telegram is found (or after 64 bytes), and
// a candidate is given up once a good telegram that starts inside it is complete before the
// candidate is decided. Every input byte ends up in exactly one item; any split of the stream
// gives the same items (docs/protocol-hsp5.md).
class Hsp5Decoder final : public FrameDecoder
{
public:
    explicit Hsp5Decoder(Role role, Hsp5Services services = Hsp5Services::Seed)
        : m_role(role)
        , m_services(services)
    {}

    void feed(QByteArrayView bytes) override;
    std::optional<Decoded> next() override;
    // Drops a partial telegram and unreported skipped bytes; the next byte is trusted again.
    void reset() override;
    qsizetype buffered() const override;

    static constexpr qsizetype kMaxSkippedRun = 64;

private:
    struct Check;
    Check check(qsizetype at, bool explain) const;
    bool goodTelegramInside(qsizetype at, qsizetype limit) const;
    std::optional<DecodeError> skip(const QString &why);
    DecodeError takeSkipped();

    Role m_role;
    Hsp5Services m_services;
    QByteArray m_buffer;     // undecided input from m_start on
    qsizetype m_start = 0;
    QByteArray m_skipped;    // bytes known to start no telegram, not reported yet
    QString m_skippedReason; // why the first of them was skipped
    bool m_inStep = true;
};

} // namespace DriveDesk
