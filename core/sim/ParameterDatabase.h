#pragma once

#include "LiveSignal.h"
#include "SevenSegment.h"
#include "protocol/Telegram.h"

#include <QByteArray>
#include <QHash>
#include <QList>
#include <QStringList>

#include <array>
#include <vector>

namespace DriveDesk::Sim {

constexpr int kSets = 8;
constexpr int kLanguages = 2; // 0 English, 1 German
using Texts = std::array<QByteArray, kLanguages>; // ASCII, at most 24 characters each

// One plaintext: the value (in place within its definition's mask) it stands for.
struct Plaintext
{
    qint32 value = 0;
    quint8 type = 0; // plaintext type bits (seed 002 2.10.1)
    Texts text;
    SegmentPattern display {};
    bool operator==(const Plaintext &) const = default;
};

// A definition index of service 12: the bits it covers and their texts.
struct PlaintextDefinitionEntry
{
    quint32 mask = 0xFFFFFFFF;
    Texts description;
    QList<Plaintext> texts;
    bool operator==(const PlaintextDefinitionEntry &) const = default;
};

// The plaintexts of one or more parameters. Several definitions make a bit-field parameter;
// only a single whole-value definition also gives 7-segment display texts.
struct Enumeration
{
    QList<PlaintextDefinitionEntry> definitions;
    bool hasDisplayTexts() const
    {
        return definitions.size() == 1 && definitions[0].mask == 0xFFFFFFFF;
    }
    bool operator==(const Enumeration &) const = default;
};

// The drive's description of one parameter, fixed for its lifetime.
struct SimParameter
{
    quint16 address = 0;
    Texts name;
    qint32 minimum = 0;
    qint32 maximum = 0;
    qint32 defaultValue = 0;
    quint32 properties1 = 0;
    quint32 properties2 = 0;
    DisplayScalingData scaling;
    int enumeration = -1; // index into ParameterDatabase::enumerations(); plaintext index - 1
    LiveSignal signal = LiveSignal::None;
    std::array<qint32, kSets> initial {}; // power-on values; [0] only unless set-programmable

    int readLevel() const { return int(properties1 & 0x7); }
    int writeLevel() const { return int((properties1 >> 3) & 0x7); }
    bool isSetProgrammable() const { return properties1 & (1u << 11); }
    bool isReadOnly() const { return (properties1 & 0x0F000000u) == 0; }
    bool allowsProcessData() const { return !(properties1 & (1u << 28)); }
};

// A parameter group (services 10, 11).
struct SimGroup
{
    quint8 page = 0;
    quint8 index = 0; // display order
    std::array<char, 2> id {};
    char shortcut = 0;
    quint16 properties = 0;
    Texts name;
    quint8 highestNumber = 0;
    int count = 0;
};

// Every group, parameter and plaintext of one simulated drive: the metadata services answer
// from it. Built once (DatabaseLoader, generated padding), then only read.
class ParameterDatabase
{
public:
    ParameterDatabase();

    // Building. Problems name what was wrong; nothing is dropped without one.
    void addGroup(const SimGroup &group);
    void addParameter(const SimParameter &parameter);
    // Changes a parameter's default and the value it starts with in every set; false when
    // there is no such parameter.
    bool setDefaultValue(quint16 address, qint32 value);
    // Leaves a parameter out (a drive that lacks it); false when there is no such parameter.
    // Call finish() afterwards.
    bool removeParameter(quint16 address);
    // Returns the index of an identical enumeration if there is one; `key` names it for
    // enumerationIndex().
    int addEnumeration(const QString &key, const Enumeration &enumeration);
    int enumerationIndex(const QString &key) const { return m_enumerationKeys.value(key, -1); }
    // Sorts parameters by address and counts them into their groups.
    void finish();
    void addProblem(const QString &problem) { m_problems << problem; }
    void addNote(const QString &note) { m_notes << note; }

    // What was wrong with the data; empty for the shipped files.
    const QStringList &problems() const { return m_problems; }
    // What the data holds that the drive deliberately leaves out, and why.
    const QStringList &notes() const { return m_notes; }
    const std::vector<SimParameter> &parameters() const { return m_parameters; }
    const std::vector<SimGroup> &groups() const { return m_groups; } // in display order
    const std::vector<Enumeration> &enumerations() const { return m_enumerations; }

    int indexOf(quint16 address) const { return m_index.value(address, -1); }
    const SimParameter *find(quint16 address) const;
    const SimGroup *group(quint8 page) const;
    // Plaintext indices (services 8, 9, 12) count from 1.
    const Enumeration *enumerationAt(quint16 plaintextIndex) const;

private:
    std::vector<SimParameter> m_parameters;
    std::vector<SimGroup> m_groups;
    std::array<qint16, 256> m_groupByPage {};
    std::vector<Enumeration> m_enumerations;
    QHash<QString, int> m_enumerationKeys;
    QHash<quint16, int> m_index;
    QStringList m_problems;
    QStringList m_notes;
};

} // namespace DriveDesk::Sim
