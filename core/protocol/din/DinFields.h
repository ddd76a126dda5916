#pragma once

#include "protocol/Telegram.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <optional>

namespace DriveDesk {

// Which telegram of a service the fields belong to. WriteResponse exists only for the duplex
// services 48-53, whose answer carries data (the error code after it is not a field).
enum class DinForm : quint8 { ReadRequest, ReadResponse, WriteRequest, WriteResponse };

// Whether the service has a data telegram in this form. The answers to the 32/33 check, a
// write of 21, a read of 48-53 and every form of Unspecified / StatusInterrogation have none.
bool hasDinFields(Service service, DinForm form);

// The field characters of a payload (after the invoke id, before the error code / ENQ / ETX),
// as seed 003 chapter 5 lays them out. Fields the form does not carry are ignored. Returns
// nothing and sets *error when the payload type does not belong to the service or a value
// cannot be expressed: a text beyond 24 characters, characters outside 20h..7Eh, a number
// wider than its field.
std::optional<QByteArray> encodeDinFields(Service service, DinForm form, const ServiceData &data,
                                          QString *error);

// The payload held by exactly these field characters (fields the form does not carry stay 0).
// Returns nothing and sets *error naming what was wrong: the character count, a character that
// is not an upper-case hex digit, a text length beyond 24 or a character outside 20h..7Eh.
std::optional<ServiceData> decodeDinFields(Service service, DinForm form, QByteArrayView characters,
                                           QString *error);

} // namespace DriveDesk
