#include "Hsp5Codec.h"

#include "Hsp5Decoder.h"
#include "Hsp5Fields.h"
#include "Hsp5Layout.h"

namespace DriveDesk {

quint8 hsp5Bcc(QByteArrayView bytes)
{
    quint8 bcc = 0;
    for (char byte : bytes)
        bcc ^= quint8(byte);
    return bcc;
}

bool Hsp5Codec::supports(Service service, Access access) const
{
    return hsp5Layout(service, access, Direction::Request, m_services).has_value();
}

QByteArray Hsp5Codec::encode(const Telegram &t, QString *error) const
{
    const auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return QByteArray();
    };
    const auto layout = hsp5Layout(t.service, t.access, t.direction, m_services);
    if (!layout) {
        const QString access = t.isWrite() ? QStringLiteral("write") : QStringLiteral("read");
        const QString direction = t.isResponse() ? QStringLiteral("response")
                                                 : QStringLiteral("request");
        const QString hint = m_services == Hsp5Services::Seed && isHsp5Extension(t.service)
                                 ? QStringLiteral(" (only with DriveDesk's HSP5 extensions)")
                                 : QString();
        return fail(QStringLiteral("HSP5 has no %1 %2 for service %3 (%4)%5")
                        .arg(access, direction)
                        .arg(int(t.service))
                        .arg(serviceName(t.service), hint));
    }
    if (t.operatorInvoke > 15 || t.inverterInvoke > 15) {
        return fail(QStringLiteral("invoke ids INV-ID-OP %1 / INV-ID-FU %2: each must be 0..15")
                        .arg(t.operatorInvoke)
                        .arg(t.inverterInvoke));
    }
    if ((t.operatorInvoke == 0) == (t.inverterInvoke == 0)) {
        return fail(QStringLiteral("invoke ids INV-ID-OP %1 / INV-ID-FU %2: exactly one must be "
                                   "non-zero")
                        .arg(t.operatorInvoke)
                        .arg(t.inverterInvoke));
    }
    if (t.data.index() != emptyDataFor(t.service).index()) {
        return fail(QStringLiteral("the payload does not belong to service %1 (%2)")
                        .arg(int(t.service))
                        .arg(serviceName(t.service)));
    }
    if (t.isResponse() && quint8(t.ack) > 15)
        return fail(QStringLiteral("acknowledge %1 is beyond 15").arg(quint8(t.ack)));

    QByteArray out;
    out.reserve(layout->lengthWith(layout->maxCount));
    out.append(char(t.operatorInvoke << 4 | t.inverterInvoke));
    out.append(char(int(t.service) | (t.isWrite() ? 0x40 : 0) | (t.isResponse() ? 0x80 : 0)));
    const qsizetype count = appendHsp5Fields(out, t);
    if (count > layout->maxCount) {
        return fail(QStringLiteral("%1 of %2 bytes is longer than the %3 HSP5 allows")
                        .arg(layout->maxCount == kHsp5MaxText ? QStringLiteral("text")
                                                              : QStringLiteral("data"))
                        .arg(count)
                        .arg(layout->maxCount));
    }
    out.append(char(hsp5Bcc(out)));
    Q_ASSERT(out.size() == layout->lengthWith(int(count)));
    return out;
}

std::unique_ptr<FrameDecoder> Hsp5Codec::makeDecoder(Role role) const
{
    return std::make_unique<Hsp5Decoder>(role, m_services);
}

} // namespace DriveDesk
