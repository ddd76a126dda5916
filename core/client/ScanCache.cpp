// How a scan uses the metadata cache: the kind parameters of each cached kind are read first;
// a drive that answers them as a cached kind gets that kind's metadata and only its values are
// read. Anything else is scanned cold, and a complete cold scan refreshes the cache.
#include "DriveScanner.h"

#include "parameters/MetadataCache.h"

namespace DriveDesk {

bool DriveScanner::probeCache()
{
    if (m_options.metadata == MetadataSource::Drive)
        return false;
    m_cache = std::make_unique<MetadataCache>(m_options.cacheDirectory.isEmpty()
                                                  ? MetadataCache::defaultDirectory()
                                                  : m_options.cacheDirectory);
    if (m_options.metadata != MetadataSource::Cache)
        return false;
    for (const QList<quint16> &addresses : m_cache->probes()) {
        m_probes.push_back({addresses, {}, false});
        m_probesPending += int(addresses.size());
    }
    for (std::size_t i = 0; i < m_probes.size(); ++i) {
        for (quint16 address : std::as_const(m_probes[i].addresses)) {
            // The kind parameters hold one value, not one per set: read as the cold scan does.
            enqueue(Service::ParameterValueStandard, ParameterValue{address, 0, 0},
                    tr("identification %1h")
                        .arg(QString::number(address, 16).toUpper().rightJustified(4, QLatin1Char('0'))),
                    [this, i, address](const Reply &reply) {
                        Probe &probe = m_probes[i];
                        if (const auto *read = reply.data<ParameterValue>())
                            probe.read.values.append({address, read->value});
                        else
                            probe.failed = true;
                        if (--m_probesPending == 0)
                            onProbed();
                    });
        }
    }
    return !m_probes.empty();
}

void DriveScanner::onProbed()
{
    for (Probe &probe : m_probes) {
        if (probe.failed)
            continue;
        std::sort(probe.read.values.begin(), probe.read.values.end(),
                  [](const KindValue &a, const KindValue &b) { return a.address < b.address; });
        QString warning;
        const std::optional<DriveDescription> cached
            = m_cache->find(probe.read, int(m_language), &warning);
        if (!warning.isEmpty())
            m_warnings.append(warning);
        if (cached) {
            m_cachedKind = probe.read;
            adoptCached(*cached);
            return;
        }
    }
    scanGroups();
}

void DriveScanner::adoptCached(const DriveDescription &cached)
{
    const auto probed = [this](quint16 address) -> std::optional<qint32> {
        for (const KindValue &value : std::as_const(m_cachedKind->values)) {
            if (value.address == address)
                return value.value;
        }
        return std::nullopt;
    };
    for (const GroupDescription &group : cached.groups) {
        const auto page = quint8(group.address >> 8);
        if (!m_options.groupPages.isEmpty() && !m_options.groupPages.contains(page))
            continue;
        ScanGroup &scanned = m_state.groups[page];
        scanned.description = group;
        scanned.description.parameters.clear();
        scanned.nextNumber = int(group.highestNumber) + 1; // nothing left to discover
        if (!m_options.parameters)
            continue;
        for (const ParameterDescription &parameter : group.parameters) {
            if (!m_options.onlyParameters.isEmpty()
                && !m_options.onlyParameters.contains(parameter.address))
                continue;
            ScanParameter &entry = scanned.parameters[parameter.number()];
            entry.description = parameter;
            entry.limitsKnown = true;
            entry.defaultKnown = true;
            if (!m_options.plaintexts)
                entry.description.plaintexts.clear();
            readVariableMetadata(page, parameter);
            const std::optional<qint32> known = probed(parameter.address);
            if (known && !parameter.isSetProgrammable())
                entry.description.values[0] = known;
            else if (wantsValue(page, parameter.number()))
                readValues(page, parameter.number(), parameter.isSetProgrammable());
        }
    }
}

// What the drive's properties say may change after power-on or at any time (seed 002, 2.6.1):
// limits that are not constant (bits 12-15), a variable default (bit 18) and a variable display
// scaling (bit 31) are read from the drive, not taken from another connection's.
void DriveScanner::readVariableMetadata(quint8 page, const ParameterDescription &parameter)
{
    const quint32 properties = parameter.properties1;
    if (properties & 0x0000F000u)
        readLimits(page, parameter.number());
    if (properties & (1u << 18))
        readDefault(page, parameter.number());
    if (properties & (1u << 31))
        readScaling(page, parameter.number());
}

// Only a complete picture of a whole drive is stored: a scan of some groups or parameters, or
// one with a metadata read that failed, would hand the next drive of the kind a partial one.
bool DriveScanner::mayStore() const
{
    if (!m_cache || m_cachedKind || !m_options.parameters || !m_options.plaintexts
        || !m_options.groupPages.isEmpty() || !m_options.onlyParameters.isEmpty()
        || !m_state.problems.isEmpty())
        return false;
    for (const auto &[page, group] : m_state.groups) {
        for (const auto &[number, parameter] : group.parameters) {
            if (parameter.metadataErrors > 0)
                return false;
        }
    }
    return true;
}

void DriveScanner::store(const DriveDescription &drive)
{
    // A drive whose identity cannot be established is never cached: it could not be told
    // apart from another kind on the next connection.
    const std::optional<DriveKind> kind = DriveIdentity::kind(drive);
    if (!kind)
        return;
    QString error;
    if (!m_cache->store(*kind, drive, &error))
        qWarning("DriveDesk: %s", qPrintable(error));
}

} // namespace DriveDesk
