// libFuzzer entry point for the HSP5 decoders (both sides of the link).
// For any input: feeding it whole, in two pieces split at a point taken from the data, and byte
// by byte gives the same items; every input byte lands in exactly one item; and every decoded
// telegram encodes back to the bytes it came from and decodes to itself again.

#include "protocol/hsp5/Hsp5Codec.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace DriveDesk;

namespace {

struct Run
{
    std::vector<Decoded> items;
    qsizetype left = 0;
};

Run decode(const Hsp5Codec &codec, Role role, const std::vector<QByteArrayView> &chunks)
{
    const auto decoder = codec.makeDecoder(role);
    Run run;
    for (QByteArrayView chunk : chunks) {
        decoder->feed(chunk);
        while (auto item = decoder->next())
            run.items.push_back(std::move(*item));
    }
    run.left = decoder->buffered();
    return run;
}

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_hsp5: %s\n", what);
    std::abort();
}

// Decoding in one piece, in two and byte by byte gives the same items, each of which encodes
// back to its bytes, and together they account for every byte.
void check(const Hsp5Codec &codec, QByteArrayView input, qsizetype cut)
{
    for (Role role : {Role::Operator, Role::Drive}) {
        const Run whole = decode(codec, role, {input});
        if (decode(codec, role, {input.first(cut), input.sliced(cut)}).items != whole.items)
            fail("a split changed the items");
        if (input.size() <= 512) {
            std::vector<QByteArrayView> bytes;
            for (qsizetype i = 0; i < input.size(); ++i)
                bytes.push_back(input.sliced(i, 1));
            if (decode(codec, role, bytes).items != whole.items)
                fail("byte by byte changed the items");
        }

        QByteArray consumed;
        for (const Decoded &item : whole.items) {
            if (const auto *error = std::get_if<DecodeError>(&item)) {
                if (error->bytes.isEmpty() || error->detail.isEmpty())
                    fail("an error without bytes or detail");
                consumed += error->bytes;
                continue;
            }
            const Telegram &telegram = std::get<Telegram>(item);
            QString why;
            const QByteArray encoded = codec.encode(telegram, &why);
            if (encoded.isEmpty())
                fail(qPrintable(QStringLiteral("a decoded telegram does not encode: ") + why));
            const Run again = decode(codec, role, {encoded});
            if (again.items.size() != 1 || again.left != 0 || again.items.front() != item)
                fail("decode(encode(t)) != t");
            consumed += encoded;
        }
        if (consumed != input.first(input.size() - whole.left))
            fail("the items do not add up to the input");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    // The seed's services alone, and with DriveDesk's extensions (a connection option).
    static const Hsp5Codec seed(Hsp5Services::Seed);
    static const Hsp5Codec extended(Hsp5Services::WithExtensions);
    const QByteArrayView input(data, qsizetype(size));
    const qsizetype cut = size == 0 ? 0 : qsizetype(data[size - 1] % (size + 1));
    check(seed, input, cut);
    check(extended, input, cut);
    return 0;
}
