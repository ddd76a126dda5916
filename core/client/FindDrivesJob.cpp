#include "FindDrivesJob.h"

#include "ValueRequests.h"

#include "parameters/DisplayScaling.h"

#include <QStringList>

#include <algorithm>

namespace DriveDesk {

namespace {

// Where a KEB F5 keeps the identification parameters a found drive is listed with: Sy.02
// inverter identifier, In.06 software version, In.10 serial number (group Sy at page 00h, In at
// 0Eh). Nothing of a drive is known before it is scanned, so they are read by address; a drive
// that keeps them elsewhere refuses the read and is listed without them. Neither protocol's
// seed promises an identification service (HSP5 has no service 13, DIN66019II reserves it):
// only service 1 (DIN66019: the legacy read) and service 5 are asked.
constexpr std::array<quint16, 3> kIdentityAddresses { 0x0002, 0x0E06, 0x0E0A };

} // namespace

QString FoundDrive::identification() const
{
    QStringList parts;
    if (!inverterIdentifier.isEmpty())
        parts << FindDrivesJob::tr("inverter identifier %1").arg(inverterIdentifier);
    if (!softwareVersion.isEmpty())
        parts << FindDrivesJob::tr("software %1").arg(softwareVersion);
    if (!serialNumber.isEmpty())
        parts << FindDrivesJob::tr("serial number %1").arg(serialNumber);
    return parts.join(FindDrivesJob::tr(", "));
}

FindDrivesJob::FindDrivesJob(const ConnectionSettings &settings, int first, int last,
                             quint16 probeAddress)
    : m_protocol(settings.protocol)
    , m_probeAddress(probeAddress)
{
    if (settings.protocol == Protocol::Hsp5) {
        m_addresses.append(settings.driveAddress);
    } else {
        for (int address = std::max(first, 0); address <= std::min(last, kLastDriveAddress);
             ++address)
            m_addresses.append(address);
    }
    if (m_addresses.isEmpty()) {
        m_problem = tr("the addresses %1..%2 hold no drive address (drives are 0..239)")
                        .arg(first)
                        .arg(last);
        promise().setProgressRange(0, 1);
    } else {
        promise().setProgressRange(0, int(m_addresses.size()));
    }
}

void FindDrivesJob::start()
{
    if (m_addresses.isEmpty()) {
        promise().setProgressValueAndText(1, m_problem);
        end();
        return;
    }
    askNext();
}

void FindDrivesJob::stopping()
{
    // A search changes nothing on the drives: what is still queued can go.
    sink().cancelPending();
    askNext();
}

Telegram FindDrivesJob::addressed(Telegram telegram, int address) const
{
    telegram.driveAddress = m_protocol == Protocol::Hsp5 ? -1 : address;
    return telegram;
}

void FindDrivesJob::askNext()
{
    if (hasEnded() || m_onTheWay > 0)
        return;
    if (isCancelled() || isStopRequested() || m_failed || m_next >= m_addresses.size()) {
        end();
        return;
    }
    const int address = m_addresses.at(m_next++);
    const Telegram probe = ValueRequests::presence(m_protocol, m_probeAddress);
    ++m_onTheWay;
    sink().probe(addressed(probe, address), [this, address](const Reply &reply, bool heard) {
        onProbed(address, reply, heard);
    });
}

void FindDrivesJob::fail(const QString &text)
{
    m_failed = true;
    promise().setProgressValueAndText(int(m_next), text);
}

void FindDrivesJob::onProbed(int address, const Reply &reply, bool heard)
{
    --m_onTheWay;
    if (isCancelled())
        return askNext();
    switch (reply.status) {
    case Reply::Status::Cancelled:
    case Reply::Status::LinkLost:
    case Reply::Status::NotConnected:
    case Reply::Status::Unsupported:
        fail(tr("drive %1: %2").arg(address).arg(reply.message()));
        return askNext();
    default:
        break;
    }
    const bool answered
        = reply.status == Reply::Status::Ok || reply.status == Reply::Status::Refused || heard;
    promise().setProgressValueAndText(int(m_next),
                                      answered ? tr("drive %1 answered").arg(address)
                                               : tr("no drive at %1").arg(address));
    if (answered)
        return identify(address);
    askNext();
}

void FindDrivesJob::identify(int address)
{
    m_drive = FoundDrive {};
    m_drive.address = address;
    m_identity = {};
    const bool scaled = sink().supports(Service::DisplayScaling, Access::Read);
    // Every request is counted before the first is submitted: an answer may come from within
    // submit() (a request that cannot be sent).
    m_onTheWay += int(kIdentityAddresses.size()) * (scaled ? 2 : 1);
    for (std::size_t i = 0; i < kIdentityAddresses.size(); ++i) {
        const quint16 parameter = kIdentityAddresses[i];
        if (scaled) {
            const Telegram scaling
                = Telegram::request(Service::DisplayScaling, Access::Read,
                                    DisplayScalingData { parameter, 0, 0, 0, 0 });
            sink().submit(addressed(scaling, address), [this, i](const Reply &reply) {
                if (const auto *data = reply.data<DisplayScalingData>())
                    m_identity[i].scaling = *data;
                onIdentityRead(reply);
            });
        }
        sink().submit(addressed(ValueRequests::readStandard(m_protocol, parameter), address),
                      [this, i](const Reply &reply) {
                          if (const auto *data = reply.data<ParameterValue>())
                              m_identity[i].value = data->value;
                          onIdentityRead(reply);
                      });
    }
}

void FindDrivesJob::onIdentityRead(const Reply &reply)
{
    --m_onTheWay;
    if (reply.isConnectionFailure() && !isCancelled() && !m_failed)
        fail(tr("drive %1: %2").arg(m_drive.address).arg(reply.message()));
    if (m_onTheWay > 0)
        return;
    reportDrive();
    askNext();
}

void FindDrivesJob::reportDrive()
{
    if (isCancelled())
        return;
    QString *const shown[]
        = { &m_drive.inverterIdentifier, &m_drive.softwareVersion, &m_drive.serialNumber };
    for (std::size_t i = 0; i < m_identity.size(); ++i) {
        const IdentityRead &read = m_identity[i];
        if (!read.value)
            continue;
        // Without its scaling (DIN66019 has no service 5) the value is shown as it came.
        const DisplayScaling scaling
            = read.scaling ? DisplayScaling(*read.scaling) : DisplayScaling();
        *shown[i] = scaling.format(*read.value);
    }
    promise().addResult(m_drive, m_found++);
}

} // namespace DriveDesk
