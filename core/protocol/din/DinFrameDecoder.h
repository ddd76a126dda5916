#pragma once

#include "protocol/Codec.h"

#include <QByteArray>
#include <QQueue>

namespace DriveDesk {

// Cuts the DIN66019 / DIN66019II byte stream of one side of the bus into telegrams and errors.
// The drive side reads requests (an `EOT a a` selection becomes the driveAddress of the
// request after it), the operator side reads answers. Both protocol variants share the bus, so
// every form is understood. The cut depends only on the bytes, never on how they arrived.
class DinFrameDecoder final : public FrameDecoder
{
public:
    explicit DinFrameDecoder(Role role);

    void feed(QByteArrayView bytes) override;
    std::optional<Decoded> next() override;
    // Drops a partial telegram and pending garbage; decoded items and a complete selection stay.
    void reset() override;
    qsizetype buffered() const override;

private:
    void emitItem(Decoded item, bool request);
    void flushGarbage();

    Role m_role = Role::Operator;
    QByteArray m_buffer; // bytes not yet cut
    QByteArray m_garbage; // the current run of bytes that belong to no telegram
    int m_selection = -1; // drive side: the EOT selection waiting for its request
    QQueue<Decoded> m_items;
};

} // namespace DriveDesk
