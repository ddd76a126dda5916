// How a scan finds a drive's parameters: each group's properties (service 10), then the names
// of its parameters number by number (service 11) until the group's count is found; a timeout is
// never taken for a parameter (docs/client.md).
#include "DriveScanner.h"

#include <set>

namespace DriveDesk {

namespace {

QString hexByte(quint8 value)
{
    return QStringLiteral("%1").arg(value, 2, 16, QLatin1Char('0')).toUpper();
}

} // namespace

void DriveScanner::probeGroup(quint8 page)
{
    enqueue(Service::GroupProperties, GroupPropertiesData{quint16(page << 8)},
            tr("group page %1h").arg(hexByte(page)),
            [this, page](const Reply &reply) { onGroupProperties(page, reply); });
}

void DriveScanner::onGroupProperties(quint8 page, const Reply &reply)
{
    const auto *properties = reply.data<GroupPropertiesData>();
    if (!properties) {
        // A refusal, whatever its ack, means there is no group on this page; anything else
        // leaves it unknown.
        if (!reply.isAnswer())
            m_state.problems.append(tr("group page %1h: %2").arg(hexByte(page), reply.message()));
        return;
    }
    ScanGroup &group = m_state.groups[page];
    GroupDescription &description = group.description;
    description.address = quint16(page << 8);
    description.index = properties->index;
    description.id = driveText(QByteArray(properties->id.data(), int(properties->id.size())));
    description.shortcut = properties->shortcut;
    description.properties = properties->properties;
    description.highestNumber = properties->highestNumber;
    description.parameterCount = int(properties->countMinusOne) + 1;

    enqueue(Service::GroupName, NameData{description.address, quint8(m_language), {}},
            tr("group %1: name").arg(description.id), [this, page](const Reply &reply) {
                // A group that refuses its name keeps an empty one; its id still shows. One
                // that does not answer is not taken for one without a name.
                if (const auto *name = reply.data<NameData>())
                    m_state.groups.at(page).description.name = driveText(name->text);
                else if (!reply.isAnswer())
                    m_state.problems.append(failure(
                        tr("group %1: name").arg(m_state.groups.at(page).description.id), reply));
            });

    if (m_options.parameters && m_options.onlyParameters.isEmpty()) {
        group.walked = true;
        askNames(page);
        return;
    }
    // No numbers are walked in order here: at most the listed ones are asked, each once.
    group.nextNumber = int(description.highestNumber) + 1;
    if (!m_options.parameters)
        return;
    std::set<quint8> listed;
    for (quint16 address : m_options.onlyParameters) {
        if (address >> 8 == page)
            listed.insert(quint8(address & 0xFF));
    }
    for (quint8 number : listed)
        askName(page, number);
}

void DriveScanner::askNames(quint8 page)
{
    ScanGroup &group = m_state.groups.at(page);
    for (int n = group.namesToAsk(); n > 0; --n)
        askName(page, quint8(group.nextNumber++));
}

void DriveScanner::askName(quint8 page, quint8 number)
{
    ScanGroup &group = m_state.groups.at(page);
    ++group.namesPending;
    enqueue(Service::ParameterName,
            NameData{quint16(group.description.address | number), quint8(m_language), {}},
            parameterWhat(page, number),
            [this, page, number](const Reply &reply) { onParameterName(page, number, reply); });
}

void DriveScanner::onParameterName(quint8 page, quint8 number, const Reply &reply)
{
    ScanGroup &group = m_state.groups.at(page);
    --group.namesPending;
    const bool unused = reply.status == Reply::Status::Refused
                        && reply.ack() == Ack::AddressInvalid;
    if (!reply.isAnswer()) {
        // Only an answer settles an address: a name or the drive's refusal. Taken for a
        // parameter, an address that gave none would use up the group's count, and its last
        // parameters would never be asked for.
        group.unsettled.append(number);
        group.unsettledReasons.append(reply.message());
    } else if (!unused) {
        // Any other failure may hide an existing parameter: keep it with the reason and read
        // the rest of what the drive says about it.
        ScanParameter &parameter = group.parameters[number];
        parameter.description.address = quint16(group.description.address | number);
        if (const auto *name = reply.data<NameData>()) {
            parameter.description.name = driveText(name->text);
        } else {
            fail(parameter, tr("name"), reply);
            ++parameter.metadataErrors;
        }
        readMetadata(page, number);
    }
    askNames(page);
}

} // namespace DriveDesk
