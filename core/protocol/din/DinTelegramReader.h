#pragma once

#include "protocol/Codec.h"

#include <QByteArrayView>

namespace DriveDesk {

// The meaning of one complete unit the DIN66019 framer has cut from the line. Each function
// checks the BCC first, then the service, then the invoke id and the fields, and returns a
// Telegram or a DecodeError naming what was wrong (driveAddress is left to the framer).

// `STX ... ETX BCC`: a write request (Role::Drive) or a read / duplex answer (Role::Operator),
// of DIN66019II (service character first) or legacy DIN66019 (hex digit first).
Decoded readDinFrame(QByteArrayView frame, Role role);

// `Svc IID fields ENQ BCC` (DIN66019II) or `aaaa ENQ` (DIN66019, no BCC).
Decoded readDinReadRequest(QByteArrayView request);

// `ACK`, `IID ACK`, `code NAK`, `IID code NAK`, `code EOT`, `IID code EOT`.
Decoded readDinShortAnswer(QByteArrayView answer);

} // namespace DriveDesk
