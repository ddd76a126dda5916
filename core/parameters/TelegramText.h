#pragma once

#include "parameters/DriveDescription.h"
#include "protocol/Telegram.h"

#include <QCoreApplication>

namespace DriveDesk {

// How a telegram reads for a user, in the installed language: parameters by id and name
// (ParameterId), values as the drive shows them (ParameterFormat), set masks as set lists
// (SetList). `drive` may be null, e.g. before a scan: ids then come from the address alone and
// values stay raw numbers. The telegram monitor shows every telegram through it.
class TelegramText
{
    Q_DECLARE_TR_FUNCTIONS(TelegramText)
public:
    // A request: "read ru.13 Actual load", "write dr.04 Motor voltage = 400 V (set 0)".
    // An answer: most answers leave the address and the set out on the wire, so an answer is
    // named only with `request`, the request it answers, and then `telegram` is the answer
    // completed with the request's fields (completeAnswer() in core/client):
    // "ru.13 Actual load: 57 %". Without a request it reads as an answer to nothing known.
    static QString describe(const Telegram &telegram, const DriveDescription *drive,
                            const Telegram *request = nullptr);
};

} // namespace DriveDesk
