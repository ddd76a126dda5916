#pragma once

#include "Hsp5SeedVectors.h"

#include "protocol/hsp5/Hsp5Codec.h"

#include <QList>
#include <QStringList>

// Helpers the HSP5 tests share: decoding a stream in pieces and showing what came out.
namespace Hsp5TestSupport {

using namespace DriveDesk;

// The side that takes a telegram in: responses go to whoever started the cycle.
inline Role receiver(const Telegram &t)
{
    return (t.operatorInvoke != 0) == t.isResponse() ? Role::Operator : Role::Drive;
}

struct Run
{
    QList<Decoded> items;
    qsizetype left = 0;
};

inline Run decode(Role role, const QList<QByteArray> &chunks)
{
    const auto decoder = Hsp5Codec(Hsp5Services::WithExtensions).makeDecoder(role);
    Run run;
    for (const QByteArray &chunk : chunks) {
        decoder->feed(chunk);
        while (auto item = decoder->next())
            run.items.append(*item);
    }
    run.left = decoder->buffered();
    return run;
}

inline Run decode(Role role, const QByteArray &bytes)
{
    return decode(role, QList<QByteArray>{bytes});
}

inline QList<QByteArray> byteByByte(const QByteArray &bytes)
{
    QList<QByteArray> chunks;
    for (char b : bytes)
        chunks.append(QByteArray(1, b));
    return chunks;
}

inline QString show(const Decoded &item)
{
    if (const auto *t = std::get_if<Telegram>(&item)) {
        return QStringLiteral("telegram op %1 fu %2: %3")
            .arg(t->operatorInvoke)
            .arg(t->inverterInvoke)
            .arg(describe(*t));
    }
    const auto &e = std::get<DecodeError>(item);
    return QStringLiteral("%1 [%2] op %3: %4")
        .arg(decodeErrorKindName(e.kind), QString::fromLatin1(e.bytes.toHex(' ')))
        .arg(e.operatorInvoke)
        .arg(e.detail);
}

inline QString show(const QList<Decoded> &items)
{
    QStringList lines;
    for (const Decoded &item : items)
        lines.append(show(item));
    return lines.join(QLatin1Char('\n'));
}

// What an item took from the stream: the error's bytes, or the telegram encoded again.
inline QByteArray bytesOf(const QList<Decoded> &items)
{
    QByteArray out;
    for (const Decoded &item : items) {
        if (const auto *t = std::get_if<Telegram>(&item))
            out += Hsp5Codec(Hsp5Services::WithExtensions).encode(*t);
        else
            out += std::get<DecodeError>(item).bytes;
    }
    return out;
}

inline const DecodeError *errorAt(const Run &run, int index)
{
    return index < run.items.size() ? std::get_if<DecodeError>(&run.items[index]) : nullptr;
}

} // namespace Hsp5TestSupport
