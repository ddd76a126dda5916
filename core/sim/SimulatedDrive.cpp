#include "SimulatedDrive.h"

#include "DriveState.h"
#include "DriveVariety.h"
#include "Services.h"


namespace DriveDesk {

namespace {

// Eight digits, as an F5's: from the seed and the drive's address, so that the drives of a
// plant differ, and the same drive connected again is the same drive (its favourites, its
// backups).
qint32 ownSerialNumber(quint32 seed, int address)
{
    quint64 x = (quint64(seed) << 32) ^ quint64(quint32(address));
    // splitmix64's finaliser: neighbouring inputs land far apart.
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    x ^= x >> 31;
    return qint32(10000000 + x % 90000000);
}

} // namespace

SimulatedDrive::SimulatedDrive(SimulatedDriveOptions options)
    : m_state(std::make_unique<Sim::DriveState>(
          Sim::databaseFor(options.kind, options.parameterCount,
                            options.metadataSeed.value_or(options.seed)),
          qBound(0, options.address, 239), options.seed))
{
    m_state->setDisplayTextAsCharacters(options.displayTextAsCharacters);
    m_state->setSerialNumber(
        options.serialNumber.value_or(ownSerialNumber(options.seed, m_state->address())));
    Sim::giveOwnSettings(*m_state);
    // A drive that is not an F5 has no text to identify it by either.
    if (options.kind != SimulatedDriveKind::Unidentified)
        m_identification = QStringLiteral("DriveDesk simulated COMBIVERT F5, %1 parameters")
                               .arg(m_state->db().parameters().size())
                               .toLatin1();
}

SimulatedDrive::~SimulatedDrive() = default;
SimulatedDrive::SimulatedDrive(SimulatedDrive &&) noexcept = default;
SimulatedDrive &SimulatedDrive::operator=(SimulatedDrive &&) noexcept = default;

int SimulatedDrive::address() const
{
    return m_state->address();
}

Telegram SimulatedDrive::respond(const Telegram &request, qint64 nowMs)
{
    m_state->advanceTo(nowMs);
    if (request.isResponse())
        return Sim::answer(request, Ack::ServiceNotAvailable, emptyDataFor(request.service));
    switch (request.service) {
    case Service::Legacy:
    case Service::ParameterValue:
    case Service::ParameterValueStandard:
    case Service::SubindexValue:
    case Service::CheckDefault:
    case Service::CheckDefaultStandard:
        return Sim::answerValueService(*m_state, request);
    case Service::Limits:
    case Service::DefaultValue:
    case Service::Properties:
    case Service::DisplayScaling:
    case Service::ParameterName:
    case Service::PlaintextIndices:
    case Service::DisplayPlaintext:
    case Service::CombivisPlaintext:
    case Service::GroupProperties:
    case Service::GroupName:
    case Service::PlaintextDefinition:
    case Service::Fieldbus:
        return Sim::answerMetadataService(*m_state, request, m_identification);
    case Service::ProcessData1:
    case Service::ProcessData2:
    case Service::Scope:
    case Service::ProcessData4:
    case Service::ProcessData5:
    case Service::ScopeRecord:
    case Service::ProcessDataDuplex1:
    case Service::ProcessDataDuplex2:
    case Service::ProcessDataDuplex3:
    case Service::ProcessDataDuplex4:
    case Service::ProcessDataDuplex5:
    case Service::ProcessDataDuplex6:
        return Sim::answerProcessDataService(*m_state, request);
    case Service::Unspecified:
    case Service::StatusInterrogation:
        break;
    }
    return Sim::answer(request, Ack::ServiceNotAvailable, emptyDataFor(request.service));
}

std::optional<qint32> SimulatedDrive::value(quint16 address, int set) const
{
    const int index = m_state->db().indexOf(address);
    if (index < 0 || set < 0 || set >= Sim::kSets)
        return std::nullopt;
    return m_state->value(index, set);
}

int SimulatedDrive::parameterCount() const
{
    return int(m_state->db().parameters().size());
}

int SimulatedDrive::groupCount() const
{
    return int(m_state->db().groups().size());
}

QString SimulatedDrive::identification() const
{
    return QString::fromLatin1(m_identification);
}

int SimulatedDrive::passwordLevel() const
{
    return m_state->passwordLevel();
}

} // namespace DriveDesk
