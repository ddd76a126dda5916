#pragma once

#include "client/RequestJob.h"
#include "link/ConnectionSettings.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <array>
#include <optional>

namespace DriveDesk {

// A drive that answered a search, with what it says about itself.
struct FoundDrive
{
    int address = -1;
    // The identification parameters as the drive shows them ("0F51h", "1.81"); empty where
    // the drive did not give one.
    QString inverterIdentifier; // Sy.02
    QString softwareVersion; // In.06
    QString serialNumber; // In.10

    // "inverter identifier 0F51h, software 1.81, serial number 1000005"; empty without any.
    QString identification() const;
};

// Asks one address after the other whether a drive answers (a service 0 read of
// `probeAddress`, DIN66019: its legacy read), each with a short wait and no retries. Any
// answer, even a refusal or a garbled one, means a drive is there; its identification
// parameters are read next, and the drive is reported (result i = the i-th drive found) before
// the next address is asked. Progress counts the addresses asked; its text says why the search
// ended early. requestStop() ends it after the address on the way, with every drive found
// reported; a cancel drops what is on the way. HSP5 is point to point: one probe of the drive.
class FindDrivesJob : public RequestJob<FoundDrive>
{
    Q_DECLARE_TR_FUNCTIONS(FindDrivesJob)
public:
    static constexpr int kLastDriveAddress = 239;

    FindDrivesJob(const ConnectionSettings &settings, int first = 0, int last = kLastDriveAddress,
                  quint16 probeAddress = 0x0000);

    // How many addresses the search asks.
    int total() const { return int(m_addresses.size()); }

private:
    // One identification parameter: its scaling (service 5) and value (service 1).
    struct IdentityRead
    {
        std::optional<DisplayScalingData> scaling;
        std::optional<qint32> value;
    };

    void start() override;
    void stopping() override;
    void askNext();
    void onProbed(int address, const Reply &reply, bool heard);
    void identify(int address);
    void onIdentityRead(const Reply &reply);
    void reportDrive();
    // The connection failed: no more addresses; `text` says why.
    void fail(const QString &text);
    Telegram addressed(Telegram telegram, int address) const;

    const Protocol m_protocol;
    const quint16 m_probeAddress;
    QList<int> m_addresses; // to ask, first to last
    QString m_problem; // why there is nothing to ask
    qsizetype m_next = 0;
    int m_onTheWay = 0;
    int m_found = 0;
    bool m_failed = false;
    FoundDrive m_drive; // the drive being identified
    std::array<IdentityRead, 3> m_identity;
};

} // namespace DriveDesk
