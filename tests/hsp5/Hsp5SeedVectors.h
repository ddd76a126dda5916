#pragma once

#include "protocol/Telegram.h"

#include <QByteArray>
#include <QList>

// Every example telegram of seed 000, sections 2.1-2.39, as bytes on the line and as the
// telegram they mean. The BCCs were worked out by hand (XOR of the bytes shown), not by the
// codec. Where an example's text length is one more than the characters it shows ("Group XY"
// with 09h, "Text for Combivis" with 12h) the text ends in a NUL, as a C string the length
// counted; "Parameter XY" with 0Ch has none.
namespace Hsp5SeedVectors {

using namespace DriveDesk;

struct Vector
{
    const char *section;
    QByteArray bytes;
    Telegram telegram;
};

inline QByteArray hex(const char *text)
{
    return QByteArray::fromHex(text);
}

inline Telegram make(quint8 op, quint8 fu, Service service, Access access, Direction direction,
                     ServiceData data, Ack ack)
{
    Telegram t = Telegram::request(service, access, std::move(data));
    t.direction = direction;
    t.operatorInvoke = op;
    t.inverterInvoke = fu;
    t.ack = ack;
    return t;
}

// The first cycle the operator starts (byte 0 = 10h) and the first the inverter starts (01h).
inline Telegram op(Service s, Access a, Direction d, ServiceData data = {}, Ack ack = Ack::Ok)
{
    if (std::holds_alternative<std::monostate>(data))
        data = emptyDataFor(s);
    return make(1, 0, s, a, d, std::move(data), ack);
}

inline Telegram inv(Service s, Access a, Direction d, ServiceData data = {}, Ack ack = Ack::Ok)
{
    if (std::holds_alternative<std::monostate>(data))
        data = emptyDataFor(s);
    return make(0, 1, s, a, d, std::move(data), ack);
}

inline QList<Vector> all()
{
    constexpr auto Rd = Access::Read;
    constexpr auto Wr = Access::Write;
    constexpr auto Req = Direction::Request;
    constexpr auto Rsp = Direction::Response;
    const QByteArray parameterXy("Parameter XY");
    const QByteArray groupXy("Group XY\0", 9);
    const QByteArray combivis("Text for Combivis\0", 18);
    const std::array<quint8, 5> offRead{' ', ' ', 'O', 'F', 'F'};
    const std::array<quint8, 5> offWrite{'.', '.', 'O', 'F', 'F'};
    using S = Service;
    return {
        {"2.1 request", hex("10 00 20 00 20 10"), op(S::ParameterValue, Rd, Req, ParameterValue{0x2000, 0x20, 0})},
        {"2.1 response", hex("10 80 00 00 00 46 00 D6"), op(S::ParameterValue, Rd, Rsp, ParameterValue{0, 0, 0x46})},
        {"2.2 request", hex("10 40 21 01 FF FF A2 40 28 BA"), op(S::ParameterValue, Wr, Req, ParameterValue{0x2101, 0x28, -24000})},
        {"2.2 response", hex("10 C0 00 D0"), op(S::ParameterValue, Wr, Rsp)},
        {"2.3 request", hex("10 01 20 00 01 30"), op(S::ParameterValueStandard, Rd, Req, ParameterValue{0x2000, 1, 0})},
        {"2.3 response", hex("10 81 00 00 00 46 00 D7"), op(S::ParameterValueStandard, Rd, Rsp, ParameterValue{0, 0, 0x46})},
        {"2.4 request", hex("10 41 21 01 FF FF A2 40 00 93"), op(S::ParameterValueStandard, Wr, Req, ParameterValue{0x2101, 0, -24000})},
        {"2.4 response", hex("10 C1 00 D1"), op(S::ParameterValueStandard, Wr, Rsp)},
        {"2.5 request", hex("10 02 21 01 32"), op(S::Limits, Rd, Req, ParameterLimits{0x2101, 0, 0})},
        {"2.5 response", hex("10 82 F2 34 56 78 1E DC BA 98 00 9A"), op(S::Limits, Rd, Rsp, ParameterLimits{0, -231451016, 0x1EDCBA98})},
        {"2.6 request", hex("01 42 21 01 12 34 56 78 23 45 67 89 E3"), inv(S::Limits, Wr, Req, ParameterLimits{0x2101, 0x12345678, 0x23456789})},
        {"2.6 response", hex("01 C2 00 C3"), inv(S::Limits, Wr, Rsp)},
        {"2.7 request", hex("10 03 21 03 31"), op(S::DefaultValue, Rd, Req, DefaultValue{0x2103, 0})},
        {"2.7 response", hex("10 83 00 00 00 46 00 D5"), op(S::DefaultValue, Rd, Rsp, DefaultValue{0, 0x46})},
        {"2.8 request", hex("01 43 21 01 FF FF A2 40 80"), inv(S::DefaultValue, Wr, Req, DefaultValue{0x2101, -24000})},
        {"2.8 response", hex("01 C3 00 C2"), inv(S::DefaultValue, Wr, Rsp)},
        {"2.9 request", hex("10 04 21 01 34"), op(S::Properties, Rd, Req, PropertiesData{0x2101, 0, 0})},
        {"2.9 response", hex("10 84 12 34 56 78 FE DC BA 98 00 9C"), op(S::Properties, Rd, Rsp, PropertiesData{0, 0x12345678, 0xFEDCBA98})},
        {"2.10 request", hex("01 44 21 01 12 34 56 78 23 45 67 89 E5"), inv(S::Properties, Wr, Req, PropertiesData{0x2101, 0x12345678, 0x23456789})},
        {"2.10 response", hex("01 C4 00 C5"), inv(S::Properties, Wr, Rsp)},
        {"2.11 request", hex("10 05 21 01 35"), op(S::DisplayScaling, Rd, Req, DisplayScalingData{0x2101, 0, 0, 0, 0})},
        {"2.11 response", hex("10 85 01 23 12 34 00 00 34 56 00 F3"), op(S::DisplayScaling, Rd, Rsp, DisplayScalingData{0, 0x0123, 0x1234, 0, 0x3456})},
        {"2.12 request", hex("01 45 21 01 12 34 02 34 08 74 00 12 1A"), inv(S::DisplayScaling, Wr, Req, DisplayScalingData{0x2101, 0x1234, 0x0234, 0x0874, 0x0012})},
        {"2.12 response", hex("01 C5 00 C4"), inv(S::DisplayScaling, Wr, Rsp)},
        {"2.13 request", hex("10 06 21 01 01 37"), op(S::ParameterName, Rd, Req, NameData{0x2101, 1, {}})},
        {"2.13 response", hex("10 86 0C") + parameterXy + hex("00 F2"), op(S::ParameterName, Rd, Rsp, NameData{0, 0, parameterXy})},
        {"2.13 negative response", hex("10 86 00 08 9E"), op(S::ParameterName, Rd, Rsp, {}, Ack::PasswordInvalid)},
        {"2.14 request", hex("01 46 21 01 01 0C") + parameterXy + hex("02"), inv(S::ParameterName, Wr, Req, NameData{0x2101, 1, parameterXy})},
        {"2.14 response", hex("01 C6 00 C7"), inv(S::ParameterName, Wr, Rsp)},
        {"2.15 request", hex("10 07 21 01 37"), op(S::PlaintextIndices, Rd, Req, PlaintextIndicesData{0x2101, 0, 0, 0, 0})},
        {"2.15 response", hex("10 87 00 17 00 09 00 24 00 36 00 9B"), op(S::PlaintextIndices, Rd, Rsp, PlaintextIndicesData{0, 0x17, 9, 0x24, 0x36})},
        {"2.16 request", hex("01 47 21 01 00 17 00 09 00 24 00 36 6A"), inv(S::PlaintextIndices, Wr, Req, PlaintextIndicesData{0x2101, 0x17, 9, 0x24, 0x36})},
        {"2.16 response", hex("01 C7 00 C6"), inv(S::PlaintextIndices, Wr, Rsp)},
        {"2.17 request", hex("10 08 00 17 00 03 00 0C"), op(S::DisplayPlaintext, Rd, Req, DisplayPlaintextData{0x17, 3, 0, 0, 0, {}})},
        {"2.17 response", hex("10 88 00 00 00 23 00 20 20 4F 46 46 00 F4"), op(S::DisplayPlaintext, Rd, Rsp, DisplayPlaintextData{0, 0, 0, 0x23, 0, offRead})},
        {"2.18 request", hex("01 48 00 17 00 03 00 01 00 00 00 23 2E 2E 4F 46 46 30"), inv(S::DisplayPlaintext, Wr, Req, DisplayPlaintextData{0x17, 3, 0, 0x23, 1, offWrite})},
        {"2.18 response", hex("01 C8 00 C9"), inv(S::DisplayPlaintext, Wr, Rsp)},
        {"2.19 request", hex("10 09 00 34 00 20 00 0D"), op(S::CombivisPlaintext, Rd, Req, CombivisPlaintextData{0x34, 0, 0x20, 0, 0, 0, {}})},
        {"2.19 response", hex("10 89 00 00 01 00 01 12") + combivis + hex("00 EB"), op(S::CombivisPlaintext, Rd, Rsp, CombivisPlaintextData{0, 0, 0, 0, 0x100, 1, combivis})},
        {"2.19 negative response", hex("10 89 00 00 01 00 01 00 03 9A"), op(S::CombivisPlaintext, Rd, Rsp, CombivisPlaintextData{0, 0, 0, 0, 0x100, 1, {}}, Ack::DataInvalid)},
        {"2.20 request", hex("01 49 00 34 00 20 01 00 00 00 01 00 12") + combivis + hex("2E"), inv(S::CombivisPlaintext, Wr, Req, CombivisPlaintextData{0x34, 0, 0x20, 1, 0x100, 0, combivis})},
        {"2.20 response", hex("01 C9 00 C8"), inv(S::CombivisPlaintext, Wr, Rsp)},
        {"2.21 request", hex("10 0A 21 00 3B"), op(S::GroupProperties, Rd, Req, GroupPropertiesData{0x2100, 0, {}, 0, 0, 0, 0})},
        {"2.21 response", hex("10 8A 01 72 75 72 00 1B 19 0D 00 E1"), op(S::GroupProperties, Rd, Rsp, GroupPropertiesData{0, 1, {'r', 'u'}, 'r', 0x1B, 0x19, 0x0D})},
        {"2.22 request", hex("01 4A 21 00 01 72 75 72 00 1B 19 0D 11"), inv(S::GroupProperties, Wr, Req, GroupPropertiesData{0x2100, 1, {'r', 'u'}, 'r', 0x1B, 0x19, 0x0D})},
        {"2.22 response", hex("01 CA 00 CB"), inv(S::GroupProperties, Wr, Rsp)},
        {"2.23 request", hex("10 0B 21 00 01 3B"), op(S::GroupName, Rd, Req, NameData{0x2100, 1, {}})},
        {"2.23 response", hex("10 8B 09") + groupXy + hex("00 EC"), op(S::GroupName, Rd, Rsp, NameData{0, 0, groupXy})},
        {"2.23 negative response", hex("10 8B 00 08 93"), op(S::GroupName, Rd, Rsp, {}, Ack::PasswordInvalid)},
        {"2.24 request", hex("01 4B 21 00 01 09") + groupXy + hex("1D"), inv(S::GroupName, Wr, Req, NameData{0x2100, 1, groupXy})},
        {"2.24 response", hex("01 CB 00 CA"), inv(S::GroupName, Wr, Rsp)},
        {"2.25 request", hex("10 0C 00 34 00 00 28"), op(S::PlaintextDefinition, Rd, Req, PlaintextDefinitionData{0x34, 0, 0, 0, 0, {}})},
        {"2.25 response", hex("10 8C 00 00 0F FF 0C 12") + combivis + hex("00 12"), op(S::PlaintextDefinition, Rd, Rsp, PlaintextDefinitionData{0, 0, 0, 0xFFF, 0x0C, combivis})},
        // The example shows only TL and ack; its byte table keeps mask and count (length 10).
        {"2.25 negative response", hex("10 8C 00 00 00 00 00 00 03 9F"), op(S::PlaintextDefinition, Rd, Rsp, {}, Ack::DataInvalid)},
        {"2.26 request", hex("01 4C 00 34 00 01 00 00 01 00 00 12") + combivis + hex("0B"), inv(S::PlaintextDefinition, Wr, Req, PlaintextDefinitionData{0x34, 0, 1, 0x100, 0, combivis})},
        {"2.26 response", hex("01 CC 00 CD"), inv(S::PlaintextDefinition, Wr, Rsp)},
        {"2.27 request", hex("10 10 00"), op(S::ProcessData1, Rd, Req)},
        {"2.27 response", hex("10 90 12 34 56 78 FE DC BA 98 00 88"), op(S::ProcessData1, Rd, Rsp, ProcessData32{{0x12345678, -19088744}})},
        {"2.28 request", hex("10 50 12 34 56 78 12 34 56 78 40"), op(S::ProcessData1, Wr, Req, ProcessData32{{0x12345678, 0x12345678}})},
        {"2.28 response", hex("10 D0 00 C0"), op(S::ProcessData1, Wr, Rsp)},
        {"2.29 request", hex("10 11 01"), op(S::ProcessData2, Rd, Req)},
        {"2.29 response", hex("10 91 12 34 56 78 FE DC BA 98 00 89"), op(S::ProcessData2, Rd, Rsp, ProcessData16{{0x1234, 0x5678, -292, -17768}})},
        {"2.30 request", hex("10 51 12 34 56 78 F4 56 00 45 AE"), op(S::ProcessData2, Wr, Req, ProcessData16{{0x1234, 0x5678, -2986, 0x45}})},
        {"2.30 response", hex("10 D1 00 C1"), op(S::ProcessData2, Wr, Rsp)},
        {"2.31 request", hex("10 12 02"), op(S::Scope, Rd, Req)},
        {"2.31 response", hex("10 92 12 34 56 78 12 34 FE DC 12 34 12 34 BA 98 00 AC"), op(S::Scope, Rd, Rsp, ScopeData{0x1234, {0x56781234, -19131852}, {0x1234, -17768}})},
        {"2.32 request", hex("10 52 12 34 56 78 12 34 F4 56 34 56 12 34 00 45 CF"), op(S::Scope, Wr, Req, ScopeData{0x1234, {0x56781234, -195677098}, {0x1234, 0x45}})},
        {"2.32 response", hex("10 D2 00 C2"), op(S::Scope, Wr, Rsp)},
        {"2.33 request", hex("10 20 21 01 20 30"), op(S::CheckDefault, Rd, Req, DefaultCheckData{0x2101, 0x20})},
        {"2.33 response", hex("10 A0 00 B0"), op(S::CheckDefault, Rd, Rsp)},
        {"2.34 request", hex("10 60 21 01 20 70"), op(S::CheckDefault, Wr, Req, DefaultCheckData{0x2101, 0x20})},
        {"2.34 response", hex("10 E0 00 F0"), op(S::CheckDefault, Wr, Rsp)},
        {"2.35 request", hex("10 21 21 01 01 10"), op(S::CheckDefaultStandard, Rd, Req, DefaultCheckData{0x2101, 1})},
        {"2.35 response", hex("10 A1 00 B1"), op(S::CheckDefaultStandard, Rd, Rsp)},
        {"2.36 request", hex("10 61 21 01 01 50"), op(S::CheckDefaultStandard, Wr, Req, DefaultCheckData{0x2101, 1})},
        {"2.36 response", hex("10 E1 00 F1"), op(S::CheckDefaultStandard, Wr, Rsp)},
        {"2.37 request", hex("10 70 12 34 56 78 23 45 67 89 E0"), op(S::ProcessDataDuplex1, Wr, Req, ProcessData32{{0x12345678, 0x23456789}})},
        {"2.37 response", hex("10 F0 12 34 56 78 FE DC BA 98 00 E8"), op(S::ProcessDataDuplex1, Wr, Rsp, ProcessData32{{0x12345678, -19088744}})},
        {"2.38 request", hex("10 71 12 34 56 78 34 56 67 89 E5"), op(S::ProcessDataDuplex2, Wr, Req, ProcessData16{{0x1234, 0x5678, 0x3456, 0x6789}})},
        {"2.38 response", hex("10 F1 23 45 45 67 FE DC BA 98 00 A5"), op(S::ProcessDataDuplex2, Wr, Rsp, ProcessData16{{0x2345, 0x4567, -292, -17768}})},
        {"2.39 request", hex("10 72 12 34 56 78 56 78 12 34 34 56 34 56 67 89 8C"), op(S::ProcessDataDuplex3, Wr, Req, ProcessParameterData{0x12345678, 0x5678, 0x1234, 0x3456, 0x34566789})},
        {"2.39 response", hex("10 F2 23 45 67 89 45 67 12 34 12 34 BA 98 00 6A"), op(S::ProcessDataDuplex3, Wr, Rsp, ProcessParameterData{0x23456789, 0x4567, 0x1234, 0, 0x1234BA98})},
    };
}

} // namespace Hsp5SeedVectors
