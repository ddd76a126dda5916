#include "Telegram.h"

#include <QCoreApplication>

namespace DriveDesk {

ServiceData emptyDataFor(Service service)
{
    switch (service) {
    case Service::Legacy:
    case Service::ParameterValue:
    case Service::ParameterValueStandard:
    case Service::SubindexValue:
        return ParameterValue{};
    case Service::Limits:
        return ParameterLimits{};
    case Service::DefaultValue:
        return DefaultValue{};
    case Service::Properties:
        return PropertiesData{};
    case Service::DisplayScaling:
        return DisplayScalingData{};
    case Service::ParameterName:
    case Service::GroupName:
        return NameData{};
    case Service::PlaintextIndices:
        return PlaintextIndicesData{};
    case Service::DisplayPlaintext:
        return DisplayPlaintextData{};
    case Service::CombivisPlaintext:
        return CombivisPlaintextData{};
    case Service::GroupProperties:
        return GroupPropertiesData{};
    case Service::PlaintextDefinition:
        return PlaintextDefinitionData{};
    case Service::Fieldbus:
        return FieldbusData{};
    case Service::ProcessData1:
    case Service::ProcessData4:
    case Service::ProcessDataDuplex1:
    case Service::ProcessDataDuplex4:
        return ProcessData32{};
    case Service::ProcessData2:
    case Service::ProcessData5:
    case Service::ProcessDataDuplex2:
    case Service::ProcessDataDuplex5:
        return ProcessData16{};
    case Service::Scope:
        return ScopeData{};
    case Service::ScopeRecord:
        return ScopeRecordData{};
    case Service::ProcessDataDuplex3:
    case Service::ProcessDataDuplex6:
        return ProcessParameterData{};
    case Service::CheckDefault:
    case Service::CheckDefaultStandard:
        return DefaultCheckData{};
    case Service::Unspecified:
    case Service::StatusInterrogation:
        break;
    }
    return std::monostate{};
}

Telegram Telegram::request(Service service, Access access, ServiceData data)
{
    Telegram t;
    t.service = service;
    t.access = access;
    t.direction = Direction::Request;
    t.data = std::move(data);
    return t;
}

Telegram Telegram::response(Ack ack) const
{
    Telegram t = *this;
    t.direction = Direction::Response;
    t.ack = ack;
    t.driveAddress = -1;
    return t;
}

QString serviceName(Service service)
{
    switch (service) {
    case Service::Unspecified: return QCoreApplication::translate("Telegram", "unspecified");
    case Service::StatusInterrogation: return QCoreApplication::translate("Telegram", "status interrogation");
    case Service::Legacy: return QCoreApplication::translate("Telegram", "DIN66019 value");
    case Service::ParameterValue: return QCoreApplication::translate("Telegram", "value (set mask)");
    case Service::ParameterValueStandard: return QCoreApplication::translate("Telegram", "value (standard set)");
    case Service::Limits: return QCoreApplication::translate("Telegram", "limits");
    case Service::DefaultValue: return QCoreApplication::translate("Telegram", "default value");
    case Service::Properties: return QCoreApplication::translate("Telegram", "properties");
    case Service::DisplayScaling: return QCoreApplication::translate("Telegram", "display scaling");
    case Service::ParameterName: return QCoreApplication::translate("Telegram", "parameter name");
    case Service::PlaintextIndices: return QCoreApplication::translate("Telegram", "plaintext indices");
    case Service::DisplayPlaintext: return QCoreApplication::translate("Telegram", "display plaintext");
    case Service::CombivisPlaintext: return QCoreApplication::translate("Telegram", "plaintext");
    case Service::GroupProperties: return QCoreApplication::translate("Telegram", "group properties");
    case Service::GroupName: return QCoreApplication::translate("Telegram", "group name");
    case Service::PlaintextDefinition: return QCoreApplication::translate("Telegram", "plaintext definition");
    case Service::Fieldbus: return QCoreApplication::translate("Telegram", "field-bus function");
    case Service::SubindexValue: return QCoreApplication::translate("Telegram", "value (subindex)");
    case Service::ProcessData1: return QCoreApplication::translate("Telegram", "process data 2x32");
    case Service::ProcessData2: return QCoreApplication::translate("Telegram", "process data 4x16");
    case Service::Scope: return QCoreApplication::translate("Telegram", "scope");
    case Service::ProcessData4: return QCoreApplication::translate("Telegram", "process data type 4");
    case Service::ProcessData5: return QCoreApplication::translate("Telegram", "process data type 5");
    case Service::ScopeRecord: return QCoreApplication::translate("Telegram", "scope record");
    case Service::CheckDefault: return QCoreApplication::translate("Telegram", "default (set mask)");
    case Service::CheckDefaultStandard: return QCoreApplication::translate("Telegram", "default (standard set)");
    case Service::ProcessDataDuplex1: return QCoreApplication::translate("Telegram", "duplex process data 2x32");
    case Service::ProcessDataDuplex2: return QCoreApplication::translate("Telegram", "duplex process data 4x16");
    case Service::ProcessDataDuplex3: return QCoreApplication::translate("Telegram", "duplex process data + parameter");
    case Service::ProcessDataDuplex4: return QCoreApplication::translate("Telegram", "duplex process data type 4");
    case Service::ProcessDataDuplex5: return QCoreApplication::translate("Telegram", "duplex process data type 5");
    case Service::ProcessDataDuplex6: return QCoreApplication::translate("Telegram", "duplex process data type 6");
    }
    return QCoreApplication::translate("Telegram", "service %1").arg(int(service));
}

namespace {

QString hex4(quint16 v)
{
    return QStringLiteral("%1h").arg(v, 4, 16, QLatin1Char('0')).toUpper().replace(
        QLatin1String("H"), QLatin1String("h"));
}

QString payload(const Telegram &t)
{
    return std::visit(
        [&](const auto &d) -> QString {
            using T = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<T, ParameterValue>)
                return QStringLiteral("%1 set %2 value %3").arg(hex4(d.address)).arg(d.set).arg(d.value);
            else if constexpr (std::is_same_v<T, ParameterLimits>)
                return QStringLiteral("%1 %2..%3").arg(hex4(d.address)).arg(d.lower).arg(d.upper);
            else if constexpr (std::is_same_v<T, DefaultValue>)
                return QStringLiteral("%1 %2").arg(hex4(d.address)).arg(d.value);
            else if constexpr (std::is_same_v<T, PropertiesData>)
                return QStringLiteral("%1 %2 %3").arg(hex4(d.address))
                    .arg(d.properties1, 8, 16, QLatin1Char('0')).arg(d.properties2, 8, 16, QLatin1Char('0'));
            else if constexpr (std::is_same_v<T, DisplayScalingData>)
                return QStringLiteral("%1 div %2 mul %3 off %4 flags %5").arg(hex4(d.address))
                    .arg(d.divisor).arg(d.multiplier).arg(d.offset).arg(d.flags, 4, 16, QLatin1Char('0'));
            else if constexpr (std::is_same_v<T, NameData>)
                return QStringLiteral("%1 lang %2 \"%3\"").arg(hex4(d.address)).arg(d.language)
                    .arg(QString::fromLatin1(d.text));
            else if constexpr (std::is_same_v<T, PlaintextIndicesData>)
                return QStringLiteral("%1 display %2/%3 combivis %4/%5").arg(hex4(d.address))
                    .arg(d.displayIndex).arg(d.displayCount).arg(d.combivisIndex).arg(d.combivisCount);
            else if constexpr (std::is_same_v<T, DisplayPlaintextData>)
                return QStringLiteral("index %1.%2 value %3").arg(d.index).arg(d.subindex).arg(d.value);
            else if constexpr (std::is_same_v<T, CombivisPlaintextData>)
                return QStringLiteral("index %1.%2.%3 value %4 \"%5\"").arg(d.index).arg(d.definition)
                    .arg(d.subindex).arg(d.value).arg(QString::fromLatin1(d.text));
            else if constexpr (std::is_same_v<T, GroupPropertiesData>)
                return QStringLiteral("%1 #%2 %3%4 highest %5 count %6").arg(hex4(d.address)).arg(d.index)
                    .arg(QLatin1Char(d.id[0])).arg(QLatin1Char(d.id[1])).arg(d.highestNumber)
                    .arg(int(d.countMinusOne) + 1);
            else if constexpr (std::is_same_v<T, PlaintextDefinitionData>)
                return QStringLiteral("index %1.%2 mask %3 count %4 \"%5\"").arg(d.index).arg(d.definition)
                    .arg(d.mask, 8, 16, QLatin1Char('0')).arg(d.count).arg(QString::fromLatin1(d.text));
            else if constexpr (std::is_same_v<T, FieldbusData>)
                return QStringLiteral("function %1 index %2.%3, %4 bytes").arg(d.function).arg(d.index)
                    .arg(d.subindex).arg(d.data.size());
            else if constexpr (std::is_same_v<T, ProcessData32>)
                return QStringLiteral("%1 %2").arg(d.values[0]).arg(d.values[1]);
            else if constexpr (std::is_same_v<T, ProcessData16>)
                return QStringLiteral("%1 %2 %3 %4").arg(d.values[0]).arg(d.values[1]).arg(d.values[2])
                    .arg(d.values[3]);
            else if constexpr (std::is_same_v<T, ScopeData>)
                return QStringLiteral("t=%1 %2 %3 %4 %5").arg(d.timestamp).arg(d.wide[0]).arg(d.wide[1])
                    .arg(d.narrow[0]).arg(d.narrow[1]);
            else if constexpr (std::is_same_v<T, ScopeRecordData>)
                return QStringLiteral("mode %1 index %2 t=%3").arg(d.mode).arg(d.index).arg(d.timestamp);
            else if constexpr (std::is_same_v<T, ProcessParameterData>)
                return QStringLiteral("%1 %2 %3 parameter %4 = %5").arg(d.value1).arg(d.value2).arg(d.value3)
                    .arg(hex4(d.parameterAddress)).arg(d.parameterValue);
            else if constexpr (std::is_same_v<T, DefaultCheckData>)
                return QStringLiteral("%1 set %2").arg(hex4(d.address)).arg(d.set);
            else
                return QString();
        },
        t.data);
}

} // namespace

QString describe(const Telegram &t)
{
    QString text = QStringLiteral("%1 %2 %3").arg(
        t.isResponse() ? QStringLiteral("response") : QStringLiteral("request"),
        t.isWrite() ? QStringLiteral("write") : QStringLiteral("read"), serviceName(t.service));
    const QString data = payload(t);
    if (!data.isEmpty())
        text += QLatin1Char(' ') + data;
    if (t.isResponse())
        text += QStringLiteral(" [%1]").arg(ackText(t.ack));
    return text;
}

} // namespace DriveDesk
