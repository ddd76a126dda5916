#include "DriveIdentity.h"

#include "ParameterFormat.h"

#include <algorithm>

namespace DriveDesk {

namespace {

const ParameterDescription *findParameter(const DriveDescription &drive,
                                          const IdentificationParameter &id,
                                          const GroupDescription **group = nullptr)
{
    const GroupDescription *found = drive.findGroup(QString::fromLatin1(id.group));
    if (!found)
        return nullptr;
    if (group)
        *group = found;
    return drive.find(quint16(found->address | id.number));
}

QString shown(const ParameterDescription &parameter, qint32 raw)
{
    return ParameterFormat(parameter).text(raw);
}

} // namespace

QList<quint16> DriveKind::addresses() const
{
    QList<quint16> addresses;
    for (const KindValue &value : values)
        addresses.append(value.address);
    return addresses;
}

const QList<IdentificationParameter> &DriveIdentity::parameters()
{
    // KEB F5: Sy.02 inverter identifier (what COMBIVIS loads its configuration by), Sy.03 power
    // unit, In.00 type, In.01 rated current, In.04 voltage class, In.06/In.07 software version
    // and date, In.10 serial number. The ratings follow from type and power unit.
    static const QList<IdentificationParameter> list{
        {"Sy", 2, true},  {"Sy", 3, true},  {"In", 0, true},  {"In", 1, false},
        {"In", 4, false}, {"In", 6, true},  {"In", 7, true},  {"In", 10, false},
    };
    return list;
}

std::optional<DriveKind> DriveIdentity::kind(const DriveDescription &drive)
{
    DriveKind kind;
    for (const IdentificationParameter &id : parameters()) {
        if (!id.namesTheKind)
            continue;
        const ParameterDescription *parameter = findParameter(drive, id);
        if (!parameter || !parameter->values[0])
            return std::nullopt;
        kind.values.append({parameter->address, *parameter->values[0]});
    }
    std::sort(kind.values.begin(), kind.values.end(),
              [](const KindValue &a, const KindValue &b) { return a.address < b.address; });
    return kind;
}

QList<DriveIdentity::Line> DriveIdentity::lines(const DriveDescription &drive)
{
    QList<Line> lines;
    if (!drive.identification.isEmpty())
        lines.append({tr("Identification"), drive.identification});
    for (const IdentificationParameter &id : parameters()) {
        const GroupDescription *group = nullptr;
        const ParameterDescription *parameter = findParameter(drive, id, &group);
        if (!parameter)
            continue;
        const QString label = tr("%1 (%2)").arg(parameter->name,
                                                parameterId(group->id, id.number));
        const std::optional<qint32> value = parameter->values[0];
        lines.append({label, value ? DriveDesk::shown(*parameter, *value)
                                   : tr("not read: %1")
                                         .arg(parameter->error.isEmpty() ? tr("no value")
                                                                         : parameter->error)});
    }
    return lines;
}

QString DriveIdentity::shown(const DriveDescription &drive, const char *group, quint8 number)
{
    const ParameterDescription *parameter = findParameter(drive, { group, number, false });
    if (!parameter || !parameter->values[0])
        return {};
    return DriveDesk::shown(*parameter, *parameter->values[0]);
}

QString DriveIdentity::summary(const DriveDescription &drive)
{
    if (!drive.identification.isEmpty())
        return drive.identification;
    const auto value = [&drive](const char *group, quint8 number) {
        return DriveIdentity::shown(drive, group, number);
    };
    const QString type = value("In", 0);
    const QString version = value("In", 6);
    const QString serial = value("In", 10);
    if (type.isEmpty())
        return {};
    if (version.isEmpty())
        return tr("Type %1").arg(type);
    if (serial.isEmpty())
        return tr("Type %1, software %2").arg(type, version);
    return tr("Type %1, software %2, serial number %3").arg(type, version, serial);
}

} // namespace DriveDesk
