#pragma once

#include "protocol/Telegram.h"

#include <QByteArray>

namespace DriveDesk::Sim {

class DriveState;

// The drive's answers, one function per family of services. Each returns the response
// telegram with payload and acknowledge; a payload of the wrong type answers ack 9.

// Services -1, 0, 1, 14 (parameter values) and 32, 33 (default values).
Telegram answerValueService(DriveState &state, const Telegram &request);
// Services 2-12 (metadata, read only: writes answer ack 7) and 13 (field-bus functions).
Telegram answerMetadataService(const DriveState &state, const Telegram &request,
                               const QByteArray &identification);
// Services 16-21 (process data, scope) and 48-53 (duplex process data).
Telegram answerProcessDataService(DriveState &state, const Telegram &request);

// The response to `request` with `ack` and `data`.
Telegram answer(const Telegram &request, Ack ack, ServiceData data);
// The response to a request whose payload does not fit its service.
Telegram malformed(const Telegram &request);

} // namespace DriveDesk::Sim
