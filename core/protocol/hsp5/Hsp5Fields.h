#pragma once

#include "protocol/Telegram.h"

#include <QByteArray>
#include <QByteArrayView>

namespace DriveDesk {

// Appends the fields between byte 1 and the BCC of an HSP5 telegram, big-endian, the
// acknowledge of a response last. The payload must be the one emptyDataFor(service) names.
// Returns the count written into the text / data length byte, or -1 where the telegram has none.
qsizetype appendHsp5Fields(QByteArray &out, const Telegram &telegram);

// Reads those fields back into telegram, whose service, access and direction are already set.
// Returns false unless the fields exactly fill the body.
bool readHsp5Fields(QByteArrayView body, Telegram &telegram);

} // namespace DriveDesk
