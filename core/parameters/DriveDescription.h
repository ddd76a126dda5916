#pragma once

#include "protocol/Telegram.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <array>
#include <optional>
#include <utility>

namespace DriveDesk {

constexpr int kParameterSets = 8;

// One text of a plaintext definition: the value (within the definition's mask) it stands for.
struct PlaintextEntry {
    qint32 value = 0;
    quint8 type = 0; // plaintext type bits (seed 002 2.11.1)
    QString text;
    bool operator==(const PlaintextEntry &) const = default;
};

// A definition index of service 12: which bits of the value it covers and their texts.
struct PlaintextDefinition {
    quint32 mask = 0;
    QString description;
    QList<PlaintextEntry> entries;
    bool operator==(const PlaintextDefinition &) const = default;
};

// What a drive says about one parameter (services 2-9, 12) and the raw values it holds.
// Metadata and values are kept apart from how they are shown: raw integers only.
struct ParameterDescription {
    quint16 address = 0;
    QString name;
    qint32 minimum = 0;
    qint32 maximum = 0;
    qint32 defaultValue = 0;
    quint32 properties1 = 0;
    quint32 properties2 = 0;
    DisplayScalingData scaling;
    PlaintextIndicesData plaintextIndices;
    QList<PlaintextDefinition> plaintexts;
    // Raw value per set. A parameter that is not set-programmable holds its one value in [0].
    // Empty where the read failed: never a guessed number.
    std::array<std::optional<qint32>, kParameterSets> values{};
    // Why a value or metadata read failed (ack text or client error), empty when all went well.
    QString error;

    quint8 number() const { return quint8(address & 0xFF); }
    bool isSetProgrammable() const { return properties1 & (1u << 11); }
    // The default in every set the parameter has ([0] alone where it is not set-programmable).
    std::array<std::optional<qint32>, kParameterSets> defaultValues() const
    {
        std::array<std::optional<qint32>, kParameterSets> defaults{};
        for (std::size_t set = 0; set < (isSetProgrammable() ? defaults.size() : 1); ++set)
            defaults[set] = defaultValue;
        return defaults;
    }
    bool operator==(const ParameterDescription &) const = default;
};

// A parameter group (services 10, 11) with the parameters found in it.
struct GroupDescription {
    quint16 address = 0;      // group page << 8
    quint8 index = 0;         // the drive's display order
    QString id;               // "ru"
    char shortcut = 0;
    quint16 properties = 0;
    quint8 highestNumber = 0;
    int parameterCount = 0;   // as the drive reports it
    QString name;
    QList<ParameterDescription> parameters;
    bool operator==(const GroupDescription &) const = default;
};

// Everything a scan found on one drive.
struct DriveDescription {
    QString protocol;       // "hsp5", ...
    QString connection;     // where it was read from
    int driveAddress = -1;
    int language = 0;
    QString identification; // service 13 function 1, where the drive has it
    // The metadata (groups, names, limits, texts) came from the metadata cache, not the drive;
    // the values were read from the drive all the same. Not part of a parameter file.
    bool metadataFromCache = false;
    QList<GroupDescription> groups;
    // Why the scan stopped early (cancelled, link lost), empty when it read everything.
    QString incompleteReason;
    // What a user should know that did not stop the scan (a damaged cache file was replaced).
    QStringList warnings;

    int parameterCount() const;
    const ParameterDescription *find(quint16 address) const;
    ParameterDescription *find(quint16 address)
    {
        return const_cast<ParameterDescription *>(std::as_const(*this).find(address));
    }
    const GroupDescription *findGroup(const QString &id) const;
    bool operator==(const DriveDescription &) const = default;
};

// "ru.03" for address 0203h, given the group's id.
QString parameterId(const QString &groupId, quint8 number);
// The id a parameter of the group is named by, in every message and table: its number counts
// from the group's first address (ParameterId::format), so a half-page group at 0280h has its
// 09 at 0289h.
QString parameterId(const GroupDescription &group, const ParameterDescription &parameter);

} // namespace DriveDesk
