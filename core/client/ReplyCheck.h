#pragma once

#include "parameters/DriveDescription.h"
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

// Why an answer cannot be what the drive holds, whatever the line and its checksum: a text
// (name, unit, plaintext) with control characters, limits whose minimum lies above their
// maximum, a display scaling that cannot be computed (divisor 0), a group with more parameters
// than numbers. Empty when nothing speaks against it. A scan reads an implausible answer again
// and reports it as an error when it stays so: it never becomes a value or metadata.
QString implausibleAnswer(const Telegram &answer);

// Why `value`, read as a value or default of `parameter`, cannot be true: it lies outside the
// parameter's own limits. Empty when it is within them.
QString implausibleValue(const ParameterDescription &parameter, qint32 value);

} // namespace DriveDesk
