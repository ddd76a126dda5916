#pragma once

#include "Acknowledge.h"

#include <QByteArray>
#include <QMetaType>
#include <QString>

#include <array>
#include <variant>

namespace DriveDesk {

// The services of the KEB protocols (seed 002). Both protocols share this service layer;
// only framing and field coding differ between HSP5 and DIN66019II.
enum class Service : qint8 {
    Unspecified = -3,         // DIN66019II short answers (IID ACK, IID code NAK/EOT) name no service
    StatusInterrogation = -2, // DIN66019: ENQ alone, collects the result of a broadcast
    Legacy = -1,              // DIN66019: telegram without service character
    ParameterValue = 0,       // enhanced set addressing (set byte is a bit mask)
    ParameterValueStandard = 1, // standard set addressing (0 = active set, 1 = Fr.09)
    Limits = 2,
    DefaultValue = 3,
    Properties = 4,
    DisplayScaling = 5,
    ParameterName = 6,
    PlaintextIndices = 7,
    DisplayPlaintext = 8,
    CombivisPlaintext = 9,
    GroupProperties = 10,
    GroupName = 11,
    PlaintextDefinition = 12,
    Fieldbus = 13,
    SubindexValue = 14,
    ProcessData1 = 16, // 2 x 32 bit
    ProcessData2 = 17, // 4 x 16 bit
    Scope = 18,        // timestamp, 2 x 32 bit, 2 x 16 bit
    ProcessData4 = 19, // 2 x 32 bit
    ProcessData5 = 20, // 4 x 16 bit
    ScopeRecord = 21,  // timestamp, 4 x 32 bit, online or offline record
    CheckDefault = 32,         // enhanced set addressing
    CheckDefaultStandard = 33, // standard set addressing
    ProcessDataDuplex1 = 48,   // 2 x 32 bit both ways
    ProcessDataDuplex2 = 49,   // 4 x 16 bit both ways
    ProcessDataDuplex3 = 50,   // process data and one parameter
    ProcessDataDuplex4 = 51,
    ProcessDataDuplex5 = 52,
    ProcessDataDuplex6 = 53,
};

enum class Direction : quint8 { Request, Response };
enum class Access : quint8 { Read, Write };

// Service payloads. As in the tables of seed 002, one struct holds the fields of a service's
// request and of its response; which of them travel depends on direction and access.
// All multi-byte numbers are host values; codecs handle byte order and hex coding.

// Services 0, 1, 14 (set = subindex) and -1 (set unused, value 16 bit on the wire).
struct ParameterValue {
    quint16 address = 0;
    quint8 set = 0;
    qint32 value = 0;
    bool operator==(const ParameterValue &) const = default;
};

// Service 2.
struct ParameterLimits {
    quint16 address = 0;
    qint32 lower = 0;
    qint32 upper = 0;
    bool operator==(const ParameterLimits &) const = default;
};

// Service 3.
struct DefaultValue {
    quint16 address = 0;
    qint32 value = 0;
    bool operator==(const DefaultValue &) const = default;
};

// Service 4.
struct PropertiesData {
    quint16 address = 0;
    quint32 properties1 = 0;
    quint32 properties2 = 0;
    bool operator==(const PropertiesData &) const = default;
};

// Service 5.
struct DisplayScalingData {
    quint16 address = 0;
    qint16 divisor = 0;
    qint16 multiplier = 0;
    qint16 offset = 0;
    quint16 flags = 0;
    bool operator==(const DisplayScalingData &) const = default;
};

// Services 6 (parameter name) and 11 (group name). Text: at most 24 bytes, Latin-1.
struct NameData {
    quint16 address = 0;
    quint8 language = 0;
    QByteArray text;
    bool operator==(const NameData &) const = default;
};

// Service 7.
struct PlaintextIndicesData {
    quint16 address = 0;
    quint16 displayIndex = 0;
    quint16 displayCount = 0;
    quint16 combivisIndex = 0;
    quint16 combivisCount = 0; // count of definition indices
    bool operator==(const PlaintextIndicesData &) const = default;
};

// Service 8: a 5-digit text for the drive's own 7-segment display.
struct DisplayPlaintextData {
    quint16 index = 0;
    quint16 subindex = 0;
    quint8 language = 0;
    qint32 value = 0;
    quint8 type = 0;
    std::array<quint8, 5> segments{};
    bool operator==(const DisplayPlaintextData &) const = default;
};

// Service 9.
struct CombivisPlaintextData {
    quint16 index = 0;
    quint8 definition = 0;
    quint8 subindex = 0;
    quint8 language = 0;
    qint32 value = 0;
    quint8 type = 0;
    QByteArray text;
    bool operator==(const CombivisPlaintextData &) const = default;
};

// Service 10.
struct GroupPropertiesData {
    quint16 address = 0;
    quint8 index = 0;           // display order 0..n
    std::array<char, 2> id{};   // e.g. 'r','u'
    char shortcut = 0;          // lower-case letter for COMBIVIS
    quint16 properties = 0;
    quint8 highestNumber = 0;   // highest parameter number in the group
    quint8 countMinusOne = 0;   // count of parameters - 1
    bool operator==(const GroupPropertiesData &) const = default;
};

// Service 12.
struct PlaintextDefinitionData {
    quint16 index = 0;
    quint8 definition = 0;
    quint8 language = 0;
    quint32 mask = 0;
    quint8 count = 0; // count of plaintexts for this definition
    QByteArray text;
    bool operator==(const PlaintextDefinitionData &) const = default;
};

// Service 13: field-bus driver functions (1 = device identification text).
struct FieldbusData {
    quint8 function = 0;
    quint16 index = 0;
    quint8 subindex = 0;
    QByteArray data; // at most 64 bytes
    bool operator==(const FieldbusData &) const = default;
};

// Services 16, 19, 48, 51.
struct ProcessData32 {
    std::array<qint32, 2> values{};
    bool operator==(const ProcessData32 &) const = default;
};

// Services 17, 20, 49, 52.
struct ProcessData16 {
    std::array<qint16, 4> values{};
    bool operator==(const ProcessData16 &) const = default;
};

// Service 18: timestamp in ms, wraps after 65535.
struct ScopeData {
    quint16 timestamp = 0;
    std::array<qint32, 2> wide{};
    std::array<qint16, 2> narrow{};
    bool operator==(const ScopeData &) const = default;
};

// Service 21 (DIN66019II): mode 0 online, 1 offline record `index`.
struct ScopeRecordData {
    quint8 mode = 0;
    quint16 index = 0;
    quint16 timestamp = 0;
    std::array<qint32, 4> values{};
    bool operator==(const ScopeRecordData &) const = default;
};

// Services 50 and 53: process data plus one parameter access. Parameter address 0: none,
// MSB clear: read that address, MSB set: write it.
struct ProcessParameterData {
    qint32 value1 = 0;
    qint16 value2 = 0;
    qint16 value3 = 0;
    quint16 parameterAddress = 0;
    qint32 parameterValue = 0;
    bool operator==(const ProcessParameterData &) const = default;
};

// Services 32 and 33.
struct DefaultCheckData {
    quint16 address = 0;
    quint8 set = 0;
    bool operator==(const DefaultCheckData &) const = default;
};

using ServiceData = std::variant<std::monostate, ParameterValue, ParameterLimits, DefaultValue,
                                 PropertiesData, DisplayScalingData, NameData, PlaintextIndicesData,
                                 DisplayPlaintextData, CombivisPlaintextData, GroupPropertiesData,
                                 PlaintextDefinitionData, FieldbusData, ProcessData32, ProcessData16,
                                 ScopeData, ScopeRecordData, ProcessParameterData, DefaultCheckData>;

// The payload type a service carries (std::monostate for Unspecified and StatusInterrogation).
ServiceData emptyDataFor(Service service);

// One telegram of either protocol, in either direction.
struct Telegram {
    Service service = Service::Unspecified;
    Access access = Access::Read;
    Direction direction = Direction::Request;
    // HSP5: INV-ID-OP (cycles the operator starts); DIN66019II: the invoke id 1..15.
    quint8 operatorInvoke = 0;
    // HSP5: INV-ID-FU (cycles the inverter starts); always 0 in DIN66019II.
    quint8 inverterInvoke = 0;
    Ack ack = Ack::Ok; // responses only
    // DIN66019(II): the EOT selection sent just before this request (0..255), -1 = none.
    int driveAddress = -1;
    ServiceData data;

    bool isResponse() const { return direction == Direction::Response; }
    bool isWrite() const { return access == Access::Write; }
    // No pointer into a temporary telegram: it would dangle when the statement ends.
    template<typename T> const T *as() const & { return std::get_if<T>(&data); }
    template<typename T> T *as() & { return std::get_if<T>(&data); }
    template<typename T> const T *as() const && = delete;
    bool operator==(const Telegram &) const = default;

    static Telegram request(Service service, Access access, ServiceData data);
    // The response to this request, with the same invoke ids and payload.
    Telegram response(Ack ack = Ack::Ok) const;
};

// The service's name in the installed language, e.g. "limits", "value (set mask)".
QString serviceName(Service service);
// A one-line decoded meaning, e.g. "read value 0203h set mask 01h -> 1234 OK", for logs.
QString describe(const Telegram &telegram);

} // namespace DriveDesk

Q_DECLARE_METATYPE(DriveDesk::Telegram)
