#include "DriveState.h"

#include "EditCheck.h"

#include "parameters/ParameterAccess.h"
#include "parameters/ParameterId.h"

#include <QDateTime>

#include <algorithm>

namespace DriveDesk {

DriveState::DriveState(QObject *parent)
    : QObject(parent)
{ }

void DriveState::setDescription(const DriveDescription &drive)
{
    emit aboutToReset();
    m_groups.clear();
    m_locations.clear();
    m_header = drive;
    m_header.groups = {};
    m_described.reset();
    m_groups.reserve(std::size_t(drive.groups.size()));
    m_locations.reserve(drive.parameterCount());
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    for (const GroupDescription &source : drive.groups) {
        Group group;
        group.header = source;
        group.header.parameters = {};
        group.rows.reserve(std::size_t(source.parameters.size()));
        const int groupRow = int(m_groups.size());
        for (const ParameterDescription &parameter : source.parameters) {
            m_locations.insert(parameter.address, { groupRow, int(group.rows.size()) });
            group.rows.emplace_back(parameter,
                                    ParameterId::format(parameter.address,
                                                        GroupAddress{ source.id, source.address }));
            const auto &values = parameter.values;
            if (std::any_of(values.begin(), values.end(), [](const auto &v) { return v.has_value(); }))
                group.rows.back().markRead(now);
        }
        m_groups.push_back(std::move(group));
    }
    emit reset();
}

const DriveDescription &DriveState::description() const
{
    if (!m_described) {
        DriveDescription drive = m_header;
        drive.groups.reserve(qsizetype(m_groups.size()));
        for (const Group &group : m_groups) {
            GroupDescription description = group.header;
            description.parameters.reserve(qsizetype(group.rows.size()));
            for (const ParameterState &row : group.rows)
                description.parameters << row.description();
            drive.groups << description;
        }
        m_described = std::move(drive);
    }
    return *m_described;
}

const ParameterState *DriveState::find(quint16 address) const
{
    const auto it = m_locations.constFind(address);
    if (it == m_locations.constEnd())
        return nullptr;
    return &m_groups[std::size_t(it->group)].rows[std::size_t(it->row)];
}

ParameterState *DriveState::findMutable(quint16 address)
{
    return const_cast<ParameterState *>(find(address));
}

const ParameterDescription *DriveState::parameter(quint16 address) const
{
    const ParameterState *found = find(address);
    return found ? &found->description() : nullptr;
}

EditText DriveState::editText(quint16 address) const
{
    const ParameterState *found = find(address);
    return found ? EditText(found->id(), &found->description())
                 : EditText(ParameterId::hexAddress(address), nullptr);
}

void DriveState::cellsChangedAt(quint16 address, int firstCell, int lastCell)
{
    m_described.reset();
    emit cellsChanged(address, firstCell, lastCell);
}

bool DriveState::setValue(quint16 address, int set, qint32 raw)
{
    ParameterState *found = findMutable(address);
    if (!found || set < 0 || set >= kParameterSets)
        return false;
    const int cell = found->cellOf(set);
    const bool wasStale = isStale(*found);
    found->markRead(QDateTime::currentMSecsSinceEpoch());
    const bool changed = found->setValue(cell, raw);
    if (wasStale) {
        m_described.reset();
        emit parameterChanged(address);
    } else if (changed) {
        cellsChangedAt(address, cell, cell);
    }
    return true;
}

bool DriveState::setValues(quint16 address, quint8 setMask, qint32 raw)
{
    if (!find(address) || setMask == 0)
        return false;
    for (int set = 0; set < kParameterSets; ++set) {
        if (setMask & (1u << set))
            setValue(address, set, raw);
    }
    return true;
}

std::optional<qint32> DriveState::value(quint16 address, int set) const
{
    const ParameterState *found = find(address);
    if (!found || set < 0 || set >= kParameterSets)
        return std::nullopt;
    return found->value(found->cellOf(set));
}

bool DriveState::putValue(quint16 address, int set, std::optional<qint32> raw)
{
    ParameterState *found = findMutable(address);
    if (!found || set < 0 || set >= kParameterSets)
        return false;
    const int cell = found->cellOf(set);
    const bool changed = found->setValue(cell, raw);
    if (found->clearEditState(cell) || changed)
        cellsChangedAt(address, cell, cell);
    return true;
}

void DriveState::setStaleSince(qint64 msecsSinceEpoch)
{
    if (msecsSinceEpoch == m_staleSinceMs)
        return;
    m_staleSinceMs = msecsSinceEpoch;
    emit staleChanged();
}

bool DriveState::isStale(quint16 address) const
{
    const ParameterState *found = find(address);
    return found && isStale(*found);
}

bool DriveState::isStale(const ParameterState &parameter) const
{
    return m_staleSinceMs != 0 && parameter.readAtMs() != 0
        && parameter.readAtMs() < m_staleSinceMs;
}

void DriveState::setPasswordLevel(PasswordLevel level)
{
    if (level == m_level)
        return;
    m_level = level;
    emit passwordLevelChanged(level);
}

bool DriveState::isAboveLevel(quint16 address) const
{
    const ParameterState *found = find(address);
    return found && EditCheck::isAboveLevel(found->properties(), m_level);
}

bool DriveState::isEditable(quint16 address) const
{
    const ParameterState *found = find(address);
    return found && isEditable(*found);
}

bool DriveState::isEditable(const ParameterState &parameter) const
{
    // Asked for every cell a view paints: the rule's yes or no, not its sentence.
    return isWritable(parameter.properties(), m_level);
}

QString DriveState::editRefusal(quint16 address) const
{
    const ParameterState *found = find(address);
    return found ? EditCheck::refusal(*found, m_level)
                 : tr("there is no parameter %1").arg(ParameterId::hexAddress(address));
}

QString DriveState::writeRefusal(quint16 address, quint8 setMask, qint32 raw) const
{
    const ParameterState *found = find(address);
    return found ? EditCheck::writeRefusal(*found, setMask, raw, m_level)
                 : tr("there is no parameter %1").arg(ParameterId::hexAddress(address));
}

void DriveState::setActiveSet(int set)
{
    if (set < 0 || set >= kParameterSets)
        set = -1;
    if (set == m_activeSet)
        return;
    m_activeSet = set;
    emit activeSetChanged(set);
}

} // namespace DriveDesk
