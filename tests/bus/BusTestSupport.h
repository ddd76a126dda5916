#pragma once

#include "protocol/Codec.h"

#include <QList>

#include <limits>

namespace DriveDesk::BusTest {

// Addresses of the simulated F5: ru.00 (read only, always there), Pn.06 bus watchdog time
// (writable, 0..1000, not set-programmable) and an address no F5 has.
constexpr quint16 kStateAddress = 0x0200;
constexpr quint16 kWritableAddress = 0x0406;
constexpr quint16 kMissingAddress = 0x7F7F;
constexpr qint64 kForever = std::numeric_limits<qint64>::max();

// The operator's end of a byte stream: encodes requests, decodes what comes back.
class Operator
{
public:
    explicit Operator(Protocol protocol)
        : m_codec(makeCodec(protocol))
        , m_decoder(m_codec->makeDecoder(Role::Operator))
    {
    }

    QByteArray encode(const Telegram &telegram) const
    {
        QString error;
        const QByteArray bytes = m_codec->encode(telegram, &error);
        if (bytes.isEmpty())
            qFatal("test telegram not encodable: %s", qPrintable(error));
        return bytes;
    }

    QList<Decoded> decode(const QByteArray &bytes)
    {
        m_decoder->feed(bytes);
        QList<Decoded> items;
        while (std::optional<Decoded> item = m_decoder->next())
            items.append(std::move(*item));
        return items;
    }

    // The telegrams among decoded items; errors count as failures of the test.
    QList<Telegram> telegrams(const QByteArray &bytes)
    {
        QList<Telegram> list;
        for (const Decoded &item : decode(bytes)) {
            if (const auto *error = std::get_if<DecodeError>(&item))
                qWarning("decode error: %s", qPrintable(error->detail));
            else
                list.append(std::get<Telegram>(item));
        }
        return list;
    }

private:
    std::unique_ptr<ProtocolCodec> m_codec;
    std::unique_ptr<FrameDecoder> m_decoder;
};

inline Telegram readValue(quint16 address, quint8 invoke, int driveAddress = -1, quint8 set = 1)
{
    Telegram t = Telegram::request(Service::ParameterValue, Access::Read,
                                   ParameterValue{address, set, 0});
    t.operatorInvoke = invoke;
    t.driveAddress = driveAddress;
    return t;
}

inline Telegram writeValue(quint16 address, qint32 value, quint8 invoke, int driveAddress = -1,
                           quint8 set = 1)
{
    Telegram t = Telegram::request(Service::ParameterValue, Access::Write,
                                   ParameterValue{address, set, value});
    t.operatorInvoke = invoke;
    t.driveAddress = driveAddress;
    return t;
}

} // namespace DriveDesk::BusTest
