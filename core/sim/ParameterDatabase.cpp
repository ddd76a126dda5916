#include "ParameterDatabase.h"

#include <algorithm>

namespace DriveDesk::Sim {

ParameterDatabase::ParameterDatabase()
{
    m_groupByPage.fill(-1);
}

void ParameterDatabase::addGroup(const SimGroup &group)
{
    if (m_groupByPage[group.page] >= 0) {
        m_problems << QStringLiteral("group page %1h is defined twice")
                          .arg(group.page, 2, 16, QLatin1Char('0'));
        return;
    }
    m_groupByPage[group.page] = qint16(m_groups.size());
    m_groups.push_back(group);
    m_groups.back().index = quint8(m_groups.size() - 1);
}

bool ParameterDatabase::setDefaultValue(quint16 address, qint32 value)
{
    const int index = indexOf(address);
    if (index < 0)
        return false;
    SimParameter &parameter = m_parameters[std::size_t(index)];
    parameter.defaultValue = value;
    parameter.initial.fill(value);
    return true;
}

bool ParameterDatabase::removeParameter(quint16 address)
{
    const int index = indexOf(address);
    if (index < 0)
        return false;
    m_parameters.erase(m_parameters.begin() + index);
    m_index.clear();
    for (std::size_t i = 0; i < m_parameters.size(); ++i)
        m_index.insert(m_parameters[i].address, int(i));
    return true;
}

void ParameterDatabase::addParameter(const SimParameter &parameter)
{
    const auto hex
        = [](quint16 v) { return QStringLiteral("%1h").arg(v, 4, 16, QLatin1Char('0')); };
    if (m_groupByPage[parameter.address >> 8] < 0) {
        m_problems
            << QStringLiteral("parameter %1 lies in no known group").arg(hex(parameter.address));
        return;
    }
    if (m_index.contains(parameter.address)) {
        m_problems << QStringLiteral("parameter %1 is defined twice").arg(hex(parameter.address));
        return;
    }
    m_index.insert(parameter.address, int(m_parameters.size()));
    m_parameters.push_back(parameter);
}

int ParameterDatabase::addEnumeration(const QString &key, const Enumeration &enumeration)
{
    int index = -1;
    for (std::size_t i = 0; i < m_enumerations.size(); ++i) {
        if (m_enumerations[i] == enumeration) {
            index = int(i);
            break;
        }
    }
    if (index < 0) {
        index = int(m_enumerations.size());
        m_enumerations.push_back(enumeration);
    }
    if (!key.isEmpty())
        m_enumerationKeys.insert(key, index);
    return index;
}

void ParameterDatabase::finish()
{
    std::sort(m_parameters.begin(), m_parameters.end(),
              [](const SimParameter &a, const SimParameter &b) { return a.address < b.address; });
    m_index.clear();
    m_index.reserve(qsizetype(m_parameters.size()));
    for (SimGroup &group : m_groups) {
        group.count = 0;
        group.highestNumber = 0;
    }
    for (std::size_t i = 0; i < m_parameters.size(); ++i) {
        const quint16 address = m_parameters[i].address;
        m_index.insert(address, int(i));
        SimGroup &group = m_groups[std::size_t(m_groupByPage[address >> 8])];
        ++group.count;
        group.highestNumber = std::max(group.highestNumber, quint8(address & 0xFF));
    }
    for (const SimGroup &group : m_groups) {
        if (group.count == 0)
            m_problems << QStringLiteral("group %1%2 has no parameters")
                              .arg(QLatin1Char(group.id[0]))
                              .arg(QLatin1Char(group.id[1]));
    }
}

const SimParameter *ParameterDatabase::find(quint16 address) const
{
    const int index = indexOf(address);
    return index < 0 ? nullptr : &m_parameters[std::size_t(index)];
}

const SimGroup *ParameterDatabase::group(quint8 page) const
{
    const qint16 index = m_groupByPage[page];
    return index < 0 ? nullptr : &m_groups[std::size_t(index)];
}

const Enumeration *ParameterDatabase::enumerationAt(quint16 plaintextIndex) const
{
    if (plaintextIndex == 0 || plaintextIndex > m_enumerations.size())
        return nullptr;
    return &m_enumerations[plaintextIndex - 1u];
}

} // namespace DriveDesk::Sim
