// How a scan reads COMBIVIS plaintexts: services 12 and 9 address them by plaintext index, so
// parameters that name the same index (and number of definitions) share one reading of it.
#include "DriveScanner.h"

namespace DriveDesk {

void DriveScanner::readPlaintexts(quint8 page, quint8 number,
                                  const PlaintextIndicesData &indices)
{
    ScanParameter &parameter = m_state.parameter(page, number);
    // Definition indices travel in one byte.
    const int count = std::min<int>(indices.combivisCount, 0x100);
    if (count < indices.combivisCount) {
        ++parameter.metadataErrors;
        parameter.errors.append(
            tr("plaintexts: the drive names %1 definitions, only %2 can be read")
                .arg(indices.combivisCount)
                .arg(count));
    }
    if (count == 0)
        return;
    const PlaintextKey key{indices.combivisIndex, count};
    const auto [entry, first] = m_state.plaintextTables.try_emplace(key);
    ScanPlaintextTable &table = entry->second;
    table.users.emplace_back(page, number);
    if (first)
        readPlaintextTable(key, parameterWhat(page, number));
    else if (table.pending == 0)
        deliverPlaintexts(table, page, number);
}

void DriveScanner::readPlaintextTable(const PlaintextKey &key, const QString &what)
{
    const auto [ptIndex, count] = key;
    ScanPlaintextTable &table = m_state.plaintextTables.at(key);
    table.definitions.resize(std::size_t(count));
    table.pending = count;
    for (int definition = 0; definition < count; ++definition) {
        const auto index = quint8(definition);
        enqueue(Service::PlaintextDefinition,
                PlaintextDefinitionData{ptIndex, index, quint8(m_language), 0, 0, {}},
                QStringLiteral("%1, %2").arg(what, tr("plaintext definition %1").arg(definition)),
                [this, key, index, what](const Reply &reply) {
                    onPlaintextDefinition(key, index, reply, what);
                });
    }
}

void DriveScanner::onPlaintextDefinition(const PlaintextKey &key, quint8 definition,
                                         const Reply &reply, const QString &what)
{
    ScanPlaintextTable &table = m_state.plaintextTables.at(key);
    const auto *d = reply.data<PlaintextDefinitionData>();
    if (!d) {
        fail(table, tr("plaintext definition %1").arg(definition), reply);
        plaintextAnswered(key);
        return;
    }
    ScanDefinition &scanned = table.definitions.at(definition);
    scanned.definition = PlaintextDefinition{d->mask, driveText(d->text), {}};
    scanned.entries.resize(d->count);
    table.pending += d->count;
    for (int subindex = 0; subindex < d->count; ++subindex) {
        const auto sub = quint8(subindex);
        const QString label = tr("plaintext %1.%2").arg(definition).arg(subindex);
        enqueue(Service::CombivisPlaintext,
                CombivisPlaintextData{key.first, definition, sub, quint8(m_language), 0, 0, {}},
                QStringLiteral("%1, %2").arg(what, label),
                [this, key, definition, sub, label](const Reply &reply) {
                    ScanPlaintextTable &t = m_state.plaintextTables.at(key);
                    if (const auto *e = reply.data<CombivisPlaintextData>())
                        t.definitions.at(definition).entries.at(sub)
                            = PlaintextEntry{e->value, e->type, driveText(e->text)};
                    else
                        fail(t, label, reply);
                    plaintextAnswered(key);
                });
    }
    plaintextAnswered(key);
}

void DriveScanner::plaintextAnswered(const PlaintextKey &key)
{
    ScanPlaintextTable &table = m_state.plaintextTables.at(key);
    if (--table.pending > 0)
        return;
    for (const auto &[page, number] : table.users)
        deliverPlaintexts(table, page, number);
}

void DriveScanner::deliverPlaintexts(const ScanPlaintextTable &table, quint8 page, quint8 number)
{
    ScanParameter &parameter = m_state.parameter(page, number);
    parameter.definitions = table.definitions;
    parameter.errors.append(table.errors);
    parameter.metadataErrors += int(table.errors.size());
    parameter.unanswered += table.unanswered;
}

void DriveScanner::deliverUnfinishedPlaintexts()
{
    for (auto &[key, table] : m_state.plaintextTables) {
        if (table.pending == 0)
            continue;
        table.pending = 0;
        for (const auto &[page, number] : table.users)
            deliverPlaintexts(table, page, number);
    }
}

} // namespace DriveDesk
