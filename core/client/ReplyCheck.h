#pragma once

#include "protocol/Codec.h"
#include "protocol/Telegram.h"

#include <QString>

namespace DriveDesk {

// Whether a decoded answer belongs to the request that waits for it: service, access, invoke
// id and, where the answer carries it, the parameter address. Empty when it does, otherwise
// why not, e.g. "invoke id 3, expected 5". An answer that does not match is never a value.
// `sent` is the telegram as it went on the wire (with its invoke id).
QString replyMismatch(Protocol protocol, const Telegram &sent, const Telegram &answer);

// The matched answer as the caller sees it: named by the request's service and access, with
// the request's own fields (address, set, language, indices) filled in where the wire does not
// carry them back, and for writes and short acknowledges the request's payload.
Telegram completeAnswer(const Telegram &sent, const Telegram &answer);

// DIN66019II: whether the request carries an invoke id (every service but the legacy DIN66019
// telegrams and the status interrogation). HSP5 requests always do.
bool carriesInvokeId(Protocol protocol, Service service);

} // namespace DriveDesk
