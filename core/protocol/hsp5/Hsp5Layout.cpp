#include "Hsp5Layout.h"

#include <array>

namespace DriveDesk {

namespace {

constexpr Hsp5Layout kNone{};
constexpr Hsp5Layout kAck{4}; // every write response: ack, BCC

constexpr Hsp5Layout fixed(int length)
{
    return Hsp5Layout{length};
}

constexpr Hsp5Layout text(int length, int countByte)
{
    return Hsp5Layout{length, countByte, kHsp5MaxText};
}

constexpr Hsp5Layout data(int length, int countByte)
{
    return Hsp5Layout{length, countByte, kHsp5MaxData};
}

struct Row
{
    Service service;
    Hsp5Layout readRequest;
    Hsp5Layout readResponse;
    Hsp5Layout writeRequest;
    Hsp5Layout writeResponse;
};

// Seed 000, chapter 2; variable lengths per PROTOCOL-NOTES ("5 + TL" with TL at byte 3 is
// length 5 and count byte 2 here). Rows marked "extension" are DriveDesk's own.
constexpr std::array kRows{
    Row{Service::ParameterValue, fixed(6), fixed(8), fixed(10), kAck},
    Row{Service::ParameterValueStandard, fixed(6), fixed(8), fixed(10), kAck},
    Row{Service::Limits, fixed(5), fixed(12), fixed(13), kAck},
    Row{Service::DefaultValue, fixed(5), fixed(8), fixed(9), kAck},
    Row{Service::Properties, fixed(5), fixed(12), fixed(13), kAck},
    Row{Service::DisplayScaling, fixed(5), fixed(12), fixed(13), kAck},
    Row{Service::ParameterName, fixed(6), text(5, 2), text(7, 5), kAck},
    Row{Service::PlaintextIndices, fixed(5), fixed(12), fixed(13), kAck},
    Row{Service::DisplayPlaintext, fixed(8), fixed(14), fixed(18), kAck},
    Row{Service::CombivisPlaintext, fixed(8), text(10, 7), text(14, 12), kAck},
    Row{Service::GroupProperties, fixed(5), fixed(12), fixed(13), kAck},
    Row{Service::GroupName, fixed(6), text(5, 2), text(7, 5), kAck},
    Row{Service::PlaintextDefinition, fixed(7), text(10, 7), text(13, 11), kAck},
    Row{Service::Fieldbus, fixed(7), data(5, 2), data(8, 6), kAck},             // extension
    Row{Service::SubindexValue, fixed(6), fixed(8), fixed(10), kAck},           // extension
    Row{Service::ProcessData1, fixed(3), fixed(12), fixed(11), kAck},
    Row{Service::ProcessData2, fixed(3), fixed(12), fixed(11), kAck},
    Row{Service::Scope, fixed(3), fixed(18), fixed(17), kAck},
    Row{Service::ProcessData4, fixed(3), fixed(12), fixed(11), kAck},           // extension
    Row{Service::ProcessData5, fixed(3), fixed(12), fixed(11), kAck},           // extension
    Row{Service::ScopeRecord, fixed(6), fixed(22), kNone, kNone},               // extension
    Row{Service::CheckDefault, fixed(6), kAck, fixed(6), kAck},
    Row{Service::CheckDefaultStandard, fixed(6), kAck, fixed(6), kAck},
    Row{Service::ProcessDataDuplex1, fixed(11), fixed(12), fixed(11), fixed(12)},
    Row{Service::ProcessDataDuplex2, fixed(11), fixed(12), fixed(11), fixed(12)},
    Row{Service::ProcessDataDuplex3, fixed(17), fixed(16), fixed(17), fixed(16)},
    Row{Service::ProcessDataDuplex4, fixed(11), fixed(12), fixed(11), fixed(12)}, // extension
    Row{Service::ProcessDataDuplex5, fixed(11), fixed(12), fixed(11), fixed(12)}, // extension
    Row{Service::ProcessDataDuplex6, fixed(17), fixed(16), fixed(17), fixed(16)}, // extension
};

const Row *rowFor(Service service)
{
    for (const Row &row : kRows) {
        if (row.service == service)
            return &row;
    }
    return nullptr;
}

} // namespace

std::optional<Service> hsp5Service(int number, Hsp5Services services)
{
    for (const Row &row : kRows) {
        if (int(row.service) != number)
            continue;
        if (services == Hsp5Services::WithExtensions || !isHsp5Extension(row.service))
            return row.service;
    }
    return std::nullopt;
}

std::optional<Hsp5Layout> hsp5Layout(Service service, Access access, Direction direction,
                                     Hsp5Services services)
{
    const Row *row = rowFor(service);
    if (!row || (services == Hsp5Services::Seed && isHsp5Extension(service)))
        return std::nullopt;
    const bool write = access == Access::Write;
    const Hsp5Layout &layout = direction == Direction::Request
                                   ? (write ? row->writeRequest : row->readRequest)
                                   : (write ? row->writeResponse : row->readResponse);
    if (layout == kNone)
        return std::nullopt;
    return layout;
}

bool isHsp5Extension(Service service)
{
    switch (service) {
    case Service::Fieldbus:
    case Service::SubindexValue:
    case Service::ProcessData4:
    case Service::ProcessData5:
    case Service::ScopeRecord:
    case Service::ProcessDataDuplex4:
    case Service::ProcessDataDuplex5:
    case Service::ProcessDataDuplex6:
        return true;
    default:
        return false;
    }
}

bool isHsp5Duplex(Service service)
{
    const int number = int(service);
    return number >= int(Service::ProcessDataDuplex1) && number <= int(Service::ProcessDataDuplex6);
}

} // namespace DriveDesk
