// The checks of a parameter file's reader (ParameterDocumentReader.cpp) beyond the types of its
// fields: what a field derived from others says, and limits no drive can have.
#include "ParameterDocumentChecks.h"

#include "DisplayScaling.h"
#include "ParameterDocument.h"
#include "ParameterProperties.h"

namespace DriveDesk::ParameterDocumentChecks {

namespace {

QString onOff(bool value)
{
    return value ? QStringLiteral("true") : QStringLiteral("false");
}

} // namespace

void checkDerived(JsonObjectReader &reader, const ParameterDescription &parameter,
                  const QList<GroupAddress> &groups)
{
    const DisplayScaling scaling(parameter.scaling);
    const ParameterProperties properties(parameter.properties1, parameter.properties2);
    if (reader.has(QStringLiteral("id"))) {
        const QString id = reader.string(QStringLiteral("id"));
        QString why;
        const std::optional<quint16> address = ParameterId::parse(id, groups, &why);
        if (reader.ok() && !address)
            reader.fail(reader.place(QStringLiteral("id")), why);
        else if (reader.ok() && *address != parameter.address)
            reader.fail(reader.place(QStringLiteral("id")),
                        ParameterDocument::tr("'%1' names %2, not the address %3")
                            .arg(id, ParameterId::hexAddress(*address),
                                 ParameterId::hexAddress(parameter.address)));
    }
    if (reader.has(QStringLiteral("unit"))) {
        const QString unit = reader.string(QStringLiteral("unit"));
        if (reader.ok() && unit != scaling.unitSymbol())
            reader.fail(reader.place(QStringLiteral("unit")),
                        ParameterDocument::tr("'%1' does not agree with scaling.flags (unit '%2')")
                            .arg(unit, scaling.unitSymbol()));
    }
    if (reader.has(QStringLiteral("decimals"))) {
        const qint64 decimals
            = reader.integer(QStringLiteral("decimals"), 0, DisplayScaling::kMaxDecimals);
        if (reader.ok() && decimals != scaling.decimals())
            reader.fail(reader.place(QStringLiteral("decimals")),
                        ParameterDocument::tr("%1 does not agree with scaling.flags (%n decimals)",
                                              nullptr, scaling.decimals())
                            .arg(decimals));
    }
    if (reader.has(QStringLiteral("setProgrammable"))) {
        const bool set = reader.boolean(QStringLiteral("setProgrammable"));
        if (reader.ok() && set != properties.isSetProgrammable())
            reader.fail(
                reader.place(QStringLiteral("setProgrammable")),
                ParameterDocument::tr("%1 does not agree with properties1 bit 11").arg(onOff(set)));
    }
    if (reader.has(QStringLiteral("readOnly"))) {
        const bool readOnly = reader.boolean(QStringLiteral("readOnly"));
        if (reader.ok() && readOnly != properties.isReadOnly())
            reader.fail(reader.place(QStringLiteral("readOnly")),
                        ParameterDocument::tr("%1 does not agree with properties2 bit 3")
                            .arg(onOff(readOnly)));
    }
}

// What no drive can report. A value outside the limits is not among them: limits and default
// may follow other parameters (properties 1 bits 12-15, bit 18), and a backup keeps what the
// drive held; the download checks values against the drive's limits.
void checkLimits(JsonObjectReader &reader, const ParameterDescription &parameter)
{
    if (parameter.minimum > parameter.maximum) {
        reader.fail(reader.place(QStringLiteral("max")),
                    ParameterDocument::tr("%1 is below min %2")
                        .arg(parameter.maximum)
                        .arg(parameter.minimum));
        return;
    }
    const ParameterProperties properties(parameter.properties1, parameter.properties2);
    const bool constant = !properties.hasVariableDefault()
        && properties.lowerLimitType() == ParameterProperties::LimitType::Constant
        && properties.upperLimitType() == ParameterProperties::LimitType::Constant;
    if (constant
        && (parameter.defaultValue < parameter.minimum
            || parameter.defaultValue > parameter.maximum)) {
        reader.fail(reader.place(QStringLiteral("default")),
                    ParameterDocument::tr("%1 is outside min..max (%2..%3), and properties1 "
                                          "says default and limits are constant")
                        .arg(parameter.defaultValue)
                        .arg(parameter.minimum)
                        .arg(parameter.maximum));
    }
}

} // namespace DriveDesk::ParameterDocumentChecks
