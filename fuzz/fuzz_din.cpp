// libFuzzer entry point for the DIN66019II / DIN66019 decoders. Every input goes through the
// operator and the drive decoder of both codecs, whole, split at a point the data chooses and
// byte by byte; the items must be the same each time. Every decoded telegram must encode again
// and decode to itself. Any difference aborts. Each input goes through a second time with every
// block check character set right: a mutation rarely keeps a BCC valid, and without this the
// field decoders behind the BCC check are seldom reached.
#include "protocol/din/DinCharacters.h"
#include "protocol/din/DinCodec.h"

#include <QList>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace DriveDesk;

namespace {

QList<Decoded> decode(const ProtocolCodec &codec, Role role, QByteArrayView bytes,
                      const QList<qsizetype> &cuts)
{
    auto decoder = codec.makeDecoder(role);
    qsizetype from = 0;
    for (qsizetype cut : cuts) {
        decoder->feed(bytes.sliced(from, cut - from));
        from = cut;
    }
    decoder->feed(bytes.sliced(from));
    QList<Decoded> items;
    while (auto item = decoder->next())
        items.append(*item);
    return items;
}

// The bytes with the character after each ETX and ENQ replaced by the BCC of what came since
// the last control character (seed 003 2.3: from the service character through ETX/ENQ; the
// address after EOT and STX itself are not covered).
QByteArray withRightBccs(QByteArrayView bytes)
{
    QByteArray repaired = bytes.toByteArray();
    qsizetype start = 0;
    for (qsizetype i = 0; i < repaired.size(); ++i) {
        const char c = repaired[i];
        if ((c == DinControl::Etx || c == DinControl::Enq) && i + 1 < repaired.size()) {
            repaired[i + 1] = char(dinBcc(QByteArrayView(repaired).sliced(start, i + 1 - start)));
            start = i + 2;
            ++i;
        } else if (c == DinControl::Eot) {
            start = qMin(i + 3, repaired.size());
            i = start - 1;
        } else if (c == DinControl::Stx || c == DinControl::Ack || c == DinControl::Nak) {
            start = i + 1;
        }
    }
    return repaired;
}

[[noreturn]] void fail(const char *what, const Telegram *telegram = nullptr)
{
    std::fprintf(stderr, "fuzz_din: %s\n", what);
    if (telegram)
        std::fprintf(stderr, "  %s\n", qPrintable(describe(*telegram)));
    std::abort();
}

void check(QByteArrayView bytes)
{
    static const DinCodec din2(Protocol::Din66019II);
    static const DinCodec din(Protocol::Din66019);
    const qsizetype size = bytes.size();
    const qsizetype split = size == 0 ? 0 : qsizetype(quint8(bytes[0]) % (size + 1));
    QList<qsizetype> everyByte;
    for (qsizetype i = 1; i < bytes.size(); ++i)
        everyByte << i;

    for (const ProtocolCodec *codec :
         { static_cast<const ProtocolCodec *>(&din2), static_cast<const ProtocolCodec *>(&din) }) {
        for (const Role role : { Role::Operator, Role::Drive }) {
            const QList<Decoded> whole = decode(*codec, role, bytes, {});
            if (decode(*codec, role, bytes, { split }) != whole)
                fail("a split changed the result");
            if (decode(*codec, role, bytes, everyByte) != whole)
                fail("feeding byte by byte changed the result");
            for (const Decoded &item : whole) {
                const auto *telegram = std::get_if<Telegram>(&item);
                if (!telegram)
                    continue;
                QString error;
                const QByteArray again = din2.encode(*telegram, &error);
                if (again.isEmpty())
                    fail(qPrintable(QStringLiteral("decoded telegram does not encode: ") + error),
                         telegram);
                if (decode(din2, role, again, {}) != QList<Decoded> { item })
                    fail("decode(encode(t)) != t", telegram);
                if (codec == &din && din.supports(telegram->service, telegram->access)
                    && din.encode(*telegram) != again) {
                    fail("the DIN66019 codec encodes differently", telegram);
                }
            }
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArrayView bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    check(bytes);
    const QByteArray repaired = withRightBccs(bytes);
    if (repaired != bytes)
        check(repaired);
    return 0;
}
