#pragma once

#include "protocol/Telegram.h"
#include "sim/SimulatedDrive.h"

#include <QByteArray>
#include <QString>

// Requests as an operator sends them, for the simulated drive's tests.
namespace SimRequests {

using namespace DriveDesk;

inline Telegram read(Service service, ServiceData data)
{
    return Telegram::request(service, Access::Read, std::move(data));
}

inline Telegram write(Service service, ServiceData data)
{
    return Telegram::request(service, Access::Write, std::move(data));
}

inline Telegram readValue(quint16 address, quint8 set = 1,
                          Service service = Service::ParameterValue)
{
    return read(service, ParameterValue { address, set, 0 });
}

inline Telegram writeValue(quint16 address, qint32 value, quint8 set = 1,
                           Service service = Service::ParameterValue)
{
    return write(service, ParameterValue { address, set, value });
}

// The value a good read answered.
inline qint32 valueOf(const Telegram &response)
{
    const auto *data = response.as<ParameterValue>();
    return data ? data->value : 0;
}

} // namespace SimRequests

namespace DriveDesk {

// Lets QCOMPARE print an acknowledge with its meaning.
inline char *toString(Ack ack)
{
    return qstrdup(qPrintable(QStringLiteral("%1 (%2)").arg(int(ack)).arg(ackText(ack))));
}

} // namespace DriveDesk
