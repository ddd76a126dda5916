#include "DinFields.h"

#include "DinCharacters.h"
#include "DinFieldCoders.h"

namespace DriveDesk {

namespace {

// Seed 003 chapter 5, one place for all three directions of use (write, measure, read), so
// that encoding and decoding cannot drift apart. `request` fields address the data (sent by
// the master), `values` are what a read answers and a write sends.
template<typename Io> void layout(Io &io, Service service, DinForm form, ServiceData &data)
{
    const bool request = form == DinForm::ReadRequest || form == DinForm::WriteRequest;
    const bool values = form != DinForm::ReadRequest;
    const bool write = form == DinForm::WriteRequest;
    switch (service) {
    case Service::Legacy: {
        auto &d = std::get<ParameterValue>(data);
        io.hex("address", d.address, 4);
        if (values)
            io.hex("value", d.value, 4);
        break;
    }
    case Service::ParameterValue:
    case Service::ParameterValueStandard:
    case Service::SubindexValue: {
        auto &d = std::get<ParameterValue>(data);
        if (request)
            io.hex("address", d.address, 4);
        if (values)
            io.hex("value", d.value, 8);
        if (request)
            io.hex(service == Service::SubindexValue ? "subindex" : "set", d.set, 2);
        break;
    }
    case Service::Limits: {
        auto &d = std::get<ParameterLimits>(data);
        if (request)
            io.hex("address", d.address, 4);
        if (values) {
            io.hex("lower limit", d.lower, 8);
            io.hex("upper limit", d.upper, 8);
        }
        break;
    }
    case Service::DefaultValue: {
        auto &d = std::get<DefaultValue>(data);
        if (request)
            io.hex("address", d.address, 4);
        if (values)
            io.hex("default value", d.value, 8);
        break;
    }
    case Service::Properties: {
        auto &d = std::get<PropertiesData>(data);
        if (request)
            io.hex("address", d.address, 4);
        if (values) {
            io.hex("properties 1", d.properties1, 8);
            io.hex("properties 2", d.properties2, 8);
        }
        break;
    }
    case Service::DisplayScaling: {
        auto &d = std::get<DisplayScalingData>(data);
        if (request)
            io.hex("address", d.address, 4);
        if (values) {
            io.hex("divisor", d.divisor, 4);
            io.hex("multiplier", d.multiplier, 4);
            io.hex("offset", d.offset, 4);
            io.hex("flags", d.flags, 4);
        }
        break;
    }
    case Service::ParameterName:
    case Service::GroupName: {
        auto &d = std::get<NameData>(data);
        if (request) {
            io.hex("address", d.address, 4);
            io.hex("language", d.language, 1);
        }
        if (values)
            io.text("name", d.text);
        break;
    }
    case Service::PlaintextIndices: {
        auto &d = std::get<PlaintextIndicesData>(data);
        if (request)
            io.hex("address", d.address, 4);
        if (values) {
            io.hex("display index", d.displayIndex, 4);
            io.hex("display count", d.displayCount, 4);
            io.hex("COMBIVIS index", d.combivisIndex, 4);
            io.hex("COMBIVIS count", d.combivisCount, 4);
        }
        break;
    }
    case Service::DisplayPlaintext: {
        auto &d = std::get<DisplayPlaintextData>(data);
        if (request) {
            io.hex("plaintext index", d.index, 4);
            io.hex("subindex", d.subindex, 4);
            io.hex("language", d.language, 1);
        }
        if (write)
            io.hex("plaintext type", d.type, 2); // the write request puts the type first
        if (values)
            io.hex("value", d.value, 8);
        if (values && !write)
            io.hex("plaintext type", d.type, 2);
        if (values) {
            for (quint8 &segment : d.segments)
                io.character("display text", segment);
        }
        break;
    }
    case Service::CombivisPlaintext: {
        auto &d = std::get<CombivisPlaintextData>(data);
        if (request) {
            io.hex("plaintext index", d.index, 4);
            io.hex("definition index", d.definition, 2);
            io.hex("subindex", d.subindex, 2);
            io.hex("language", d.language, 1);
        }
        if (write)
            io.hex("plaintext type", d.type, 2);
        if (values)
            io.hex("value", d.value, 8);
        if (values && !write)
            io.hex("plaintext type", d.type, 2);
        if (values)
            io.text("plaintext", d.text);
        break;
    }
    case Service::GroupProperties: {
        auto &d = std::get<GroupPropertiesData>(data);
        if (request)
            io.hex("group address", d.address, 4);
        if (values) {
            io.hex("group index", d.index, 2);
            io.character("group id", d.id[0]);
            io.character("group id", d.id[1]);
            io.character("shortcut", d.shortcut);
            io.hex("group properties", d.properties, 4);
            io.hex("highest parameter number", d.highestNumber, 2);
            io.hex("parameter count", d.countMinusOne, 2);
        }
        break;
    }
    case Service::PlaintextDefinition: {
        auto &d = std::get<PlaintextDefinitionData>(data);
        if (request) {
            io.hex("plaintext index", d.index, 4);
            io.hex("definition index", d.definition, 2);
            io.hex("language", d.language, 1);
        }
        if (values) {
            io.hex("bit mask", d.mask, 8);
            io.hex("plaintext count", d.count, 2);
            io.text("description", d.text);
        }
        break;
    }
    case Service::Fieldbus: {
        auto &d = std::get<FieldbusData>(data);
        if (request) {
            io.hex("function", d.function, 2);
            io.hex("index", d.index, 4);
            io.hex("subindex", d.subindex, 2);
        }
        if (values)
            io.bytes("data", d.data);
        break;
    }
    case Service::ProcessData1:
    case Service::ProcessData4:
    case Service::ProcessDataDuplex1:
    case Service::ProcessDataDuplex4: {
        auto &d = std::get<ProcessData32>(data);
        if (values) {
            for (qint32 &value : d.values)
                io.hex("process data", value, 8);
        }
        break;
    }
    case Service::ProcessData2:
    case Service::ProcessData5:
    case Service::ProcessDataDuplex2:
    case Service::ProcessDataDuplex5: {
        auto &d = std::get<ProcessData16>(data);
        if (values) {
            for (qint16 &value : d.values)
                io.hex("process data", value, 4);
        }
        break;
    }
    case Service::Scope: {
        auto &d = std::get<ScopeData>(data);
        if (values) {
            io.hex("timestamp", d.timestamp, 4);
            for (qint32 &value : d.wide)
                io.hex("scope data", value, 8);
            for (qint16 &value : d.narrow)
                io.hex("scope data", value, 4);
        }
        break;
    }
    case Service::ScopeRecord: {
        auto &d = std::get<ScopeRecordData>(data);
        if (request) {
            io.hex("mode", d.mode, 1);
            io.hex("record index", d.index, 4);
        }
        if (values) {
            io.hex("timestamp", d.timestamp, 4);
            for (qint32 &value : d.values)
                io.hex("scope data", value, 8);
        }
        break;
    }
    case Service::ProcessDataDuplex3:
    case Service::ProcessDataDuplex6: {
        auto &d = std::get<ProcessParameterData>(data);
        io.hex("process data 1", d.value1, 8);
        io.hex("process data 2", d.value2, 4);
        io.hex("process data 3", d.value3, 4);
        if (request)
            io.hex("parameter address", d.parameterAddress, 4);
        io.hex("parameter value", d.parameterValue, 8);
        break;
    }
    case Service::CheckDefault:
    case Service::CheckDefaultStandard: {
        auto &d = std::get<DefaultCheckData>(data);
        io.hex("address", d.address, 4);
        io.hex("set", d.set, 2);
        break;
    }
    case Service::Unspecified:
    case Service::StatusInterrogation:
        break;
    }
}

} // namespace

bool hasDinFields(Service service, DinForm form)
{
    if (service == Service::Legacy)
        return form != DinForm::WriteResponse;
    if (isDinDuplex(service))
        return form == DinForm::WriteRequest || form == DinForm::WriteResponse;
    switch (form) {
    case DinForm::ReadRequest:
        return isDinReadable(service);
    case DinForm::ReadResponse:
        return isDinReadable(service) && service != Service::CheckDefault
            && service != Service::CheckDefaultStandard;
    case DinForm::WriteRequest:
        return isDinWritable(service);
    case DinForm::WriteResponse:
        break;
    }
    return false;
}

std::optional<QByteArray> encodeDinFields(Service service, DinForm form, const ServiceData &data,
                                          QString *error)
{
    if (!hasDinFields(service, form)) {
        *error = QStringLiteral("%1 has no such telegram in DIN66019II").arg(serviceName(service));
        return std::nullopt;
    }
    if (data.index() != emptyDataFor(service).index()) {
        *error = QStringLiteral("the payload does not belong to service %1").arg(int(service));
        return std::nullopt;
    }
    ServiceData copy = data;
    DinFieldWriter writer;
    layout(writer, service, form, copy);
    if (!writer.m_error.isEmpty()) {
        *error = writer.m_error;
        return std::nullopt;
    }
    return writer.m_out;
}

std::optional<ServiceData> decodeDinFields(Service service, DinForm form, QByteArrayView characters,
                                           QString *error)
{
    ServiceData data = emptyDataFor(service);
    if (!hasDinFields(service, form)) {
        *error = QStringLiteral("%1 has no such telegram in DIN66019II").arg(serviceName(service));
        return std::nullopt;
    }
    DinFieldMeasure measure(characters);
    layout(measure, service, form, data);
    if (measure.m_known && measure.m_size != characters.size()) {
        *error = QStringLiteral("%1 data characters, expected %2")
                     .arg(characters.size())
                     .arg(measure.m_size);
        return std::nullopt;
    }
    DinFieldReader reader(characters);
    layout(reader, service, form, data);
    if (reader.m_error.isEmpty() && reader.m_pos != characters.size()) {
        reader.fail(QStringLiteral("%1 data characters, %2 left over")
                        .arg(characters.size())
                        .arg(characters.size() - reader.m_pos));
    }
    if (!reader.m_error.isEmpty()) {
        *error = reader.m_error;
        return std::nullopt;
    }
    return data;
}

} // namespace DriveDesk
