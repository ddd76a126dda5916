#pragma once

#include "protocol/Telegram.h"

#include <QString>

#include <memory>
#include <optional>

namespace DriveDesk {

namespace Sim {
class DriveState;
}

// What metadata a simulated drive has: one kind, one metadata, as the metadata cache expects.
enum class SimulatedDriveKind : quint8 {
    Standard,     // the simulated F5 (padded to parameterCount where asked)
    Other,        // other software: a higher version (In.06) and more parameters
    Unidentified, // not an F5: no identification parameters (Sy.02, Sy.03, In.00 ... In.10)
                  // and no service 13 text
};

struct SimulatedDriveOptions
{
    int address = 1; // DIN66019II drive address 0..239; it also picks a few user settings
    int parameterCount = 0; // 0: the standard simulated F5; N > standard: pad with generated
                            // groups/parameters to N
    quint32 seed = 1; // generated parameters, measurement noise
    // In.10. Unset: one of its own, from the seed and the address: two simulated drives of a
    // plant are two drives.
    std::optional<qint32> serialNumber = std::nullopt;
    // Service 8: an HSP5 drive sends its display text as 7-segment patterns (seed 000 2.17),
    // a DIN66019II drive as five characters (seed 003 5.15), since a 7-bit line has no room
    // for the patterns.
    bool displayTextAsCharacters = false;
    SimulatedDriveKind kind = SimulatedDriveKind::Standard;
    // Generated parameters come from this seed where it is given, so that drives of one kind on
    // a bus, each with a seed of its own, have the same metadata.
    std::optional<quint32> metadataSeed = std::nullopt;
};

// A drive that answers telegrams like a KEB COMBIVERT F5, built from data about real F5s
// (docs/simulated-drive.md). Plain class, not a QObject; not thread-safe: one thread at a
// time calls it. respond() is cheap: no I/O, no allocation beyond the answer.
class SimulatedDrive
{
public:
    explicit SimulatedDrive(SimulatedDriveOptions options = {});
    ~SimulatedDrive();
    SimulatedDrive(SimulatedDrive &&) noexcept;
    SimulatedDrive &operator=(SimulatedDrive &&) noexcept;

    // The address it was given (Sy.06 starts there; writing Sy.06 does not move the drive).
    int address() const;

    // Answers one request (any service, either access) as the drive would: the response
    // telegram with the right payload and acknowledge. Protocol-agnostic (the codecs frame it).
    // nowMs: a monotonic clock in ms that drives the live signals.
    Telegram respond(const Telegram &request, qint64 nowMs);

    // The value the drive holds or shows now in `set`, ignoring password levels; nothing for
    // an unknown address or a set outside 0..7. For tests.
    std::optional<qint32> value(quint16 address, int set) const;
    int parameterCount() const;
    int groupCount() const;
    QString identification() const; // the service 13 function 1 text

    // The password level in force (0..7; reading ud.01 gives -1 - level).
    int passwordLevel() const;

private:
    std::unique_ptr<Sim::DriveState> m_state;
    QByteArray m_identification;
};

} // namespace DriveDesk
