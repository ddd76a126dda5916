#include "TelegramText.h"

#include "ParameterFormat.h"
#include "ParameterId.h"
#include "SetList.h"

#include <QStringList>

namespace DriveDesk {

namespace {

QString hexNumber(quint32 value, int digits)
{
    return QString::number(value, 16).toUpper().rightJustified(digits, QLatin1Char('0'))
        + QLatin1Char('h');
}

// The numbers of a payload, for the services that have no sentence of their own.
QString numbersOf(const ServiceData &data)
{
    return std::visit(
        [](const auto &d) -> QString {
            using T = std::decay_t<decltype(d)>;
            QStringList numbers;
            if constexpr (std::is_same_v<T, ProcessData32> || std::is_same_v<T, ProcessData16>) {
                for (const auto value : d.values)
                    numbers << QString::number(value);
            } else if constexpr (std::is_same_v<T, ScopeRecordData>) {
                numbers << QString::number(d.mode) << QString::number(d.index)
                        << QString::number(d.timestamp);
                for (const auto value : d.values)
                    numbers << QString::number(value);
            } else if constexpr (std::is_same_v<T, ProcessParameterData>) {
                numbers << QString::number(d.value1) << QString::number(d.value2)
                        << QString::number(d.value3) << hexNumber(d.parameterAddress, 4)
                        << QString::number(d.parameterValue);
            } else if constexpr (std::is_same_v<T, FieldbusData>) {
                numbers << QString::number(d.function) << QString::number(d.index)
                        << QString::number(d.subindex) << QString::number(d.data.size());
            }
            return numbers.join(QLatin1Char(' '));
        },
        data);
}

// Names parameters and groups from the drive's description, where there is one.
class Namer
{
public:
    explicit Namer(const DriveDescription *drive)
        : m_drive(drive)
    {
        if (drive)
            m_groups = ParameterId::groupsOf(*drive);
    }

    const ParameterDescription *parameter(quint16 address) const
    {
        return m_drive ? m_drive->find(address) : nullptr;
    }

    // "ru.13 Actual load", or "020Dh" where no description knows it.
    QString parameterName(quint16 address) const
    {
        const QString id = ParameterId::format(address, m_groups);
        const ParameterDescription *p = parameter(address);
        return p && !p->name.isEmpty() ? id + QLatin1Char(' ') + p->name : id;
    }

    // "ru Run display", or "0200h".
    QString groupName(quint16 address) const
    {
        const std::optional<GroupAddress> group = ParameterId::groupOf(address, m_groups);
        if (!group || !m_drive)
            return ParameterId::hexAddress(address);
        for (const GroupDescription &described : m_drive->groups) {
            if (described.address == group->address && !described.name.isEmpty())
                return described.id + QLatin1Char(' ') + described.name;
        }
        return group->id;
    }

    // As the drive shows it: plaintext, or scaled with unit.
    QString value(quint16 address, qint32 raw) const
    {
        const ParameterDescription *p = parameter(address);
        return p ? ParameterFormat(*p).text(raw) : QString::number(raw);
    }

    // Scaled with unit, never a plaintext (limits).
    QString number(quint16 address, qint32 raw) const
    {
        const ParameterDescription *p = parameter(address);
        return p ? ParameterFormat(*p).number(raw, true) : QString::number(raw);
    }

private:
    const DriveDescription *m_drive = nullptr;
    QList<GroupAddress> m_groups;
};

// The sets a value telegram addresses, as a note after the parameter: " (set 0)". Nothing
// for the active set, which is what a plain read means.
QString setNote(Service service, quint8 set)
{
    switch (service) {
    case Service::ParameterValue:
    case Service::CheckDefault:
        return QStringLiteral(" (%1)").arg(SetList::text(set));
    case Service::ParameterValueStandard:
    case Service::CheckDefaultStandard:
        return set == 0 ? QString() : QStringLiteral(" (%1)").arg(SetList::standardSetText(set));
    case Service::SubindexValue:
        return TelegramText::tr(" (subindex %1)").arg(set);
    default:
        return {};
    }
}

QString requestText(const Telegram &t, const Namer &names)
{
    const bool write = t.isWrite();
    if (const auto *d = t.as<ParameterValue>()) {
        const QString note = setNote(t.service, d->set);
        return write
            ? TelegramText::tr("write %1 = %2%3")
                  .arg(names.parameterName(d->address), names.value(d->address, d->value), note)
            : TelegramText::tr("read %1%2").arg(names.parameterName(d->address), note);
    }
    if (const auto *d = t.as<DefaultCheckData>()) {
        const QString note = setNote(t.service, d->set);
        return write ? TelegramText::tr("reset %1 to its default%2")
                           .arg(names.parameterName(d->address), note)
                     : TelegramText::tr("check whether %1 holds its default%2")
                           .arg(names.parameterName(d->address), note);
    }
    if (!write) {
        if (const auto *d = t.as<ParameterLimits>())
            return TelegramText::tr("read the limits of %1").arg(names.parameterName(d->address));
        if (const auto *d = t.as<DefaultValue>())
            return TelegramText::tr("read the default of %1").arg(names.parameterName(d->address));
        if (const auto *d = t.as<PropertiesData>())
            return TelegramText::tr("read the properties of %1")
                .arg(names.parameterName(d->address));
        if (const auto *d = t.as<DisplayScalingData>())
            return TelegramText::tr("read the display scaling of %1")
                .arg(names.parameterName(d->address));
        if (const auto *d = t.as<NameData>()) {
            return t.service == Service::GroupName
                ? TelegramText::tr("read the name of group %1").arg(names.groupName(d->address))
                : TelegramText::tr("read the name of %1").arg(names.parameterName(d->address));
        }
        if (const auto *d = t.as<PlaintextIndicesData>())
            return TelegramText::tr("read the plaintext indices of %1")
                .arg(names.parameterName(d->address));
        if (const auto *d = t.as<GroupPropertiesData>())
            return TelegramText::tr("read the properties of group %1")
                .arg(names.groupName(d->address));
        if (const auto *d = t.as<CombivisPlaintextData>())
            return TelegramText::tr("read plaintext %1.%2.%3")
                .arg(d->index)
                .arg(d->definition)
                .arg(d->subindex);
        if (const auto *d = t.as<PlaintextDefinitionData>())
            return TelegramText::tr("read plaintext definition %1.%2")
                .arg(d->index)
                .arg(d->definition);
        if (const auto *d = t.as<DisplayPlaintextData>())
            return TelegramText::tr("read display plaintext %1.%2 for %3")
                .arg(d->index)
                .arg(d->subindex)
                .arg(d->value);
    }
    const QString numbers = numbersOf(t.data);
    const QString service = serviceName(t.service);
    if (numbers.isEmpty())
        return write ? TelegramText::tr("write %1").arg(service)
                     : TelegramText::tr("read %1").arg(service);
    return write ? TelegramText::tr("write %1: %2").arg(service, numbers)
                 : TelegramText::tr("read %1: %2").arg(service, numbers);
}

QString answerText(const Telegram &t, const Namer &names)
{
    if (const auto *d = t.as<ParameterValue>()) {
        const QString note = setNote(t.service, d->set);
        const QString name = names.parameterName(d->address);
        const QString value = names.value(d->address, d->value);
        return t.isWrite() ? TelegramText::tr("written: %1 = %2%3").arg(name, value, note)
                           : TelegramText::tr("%1: %2%3").arg(name, value, note);
    }
    if (const auto *d = t.as<DefaultCheckData>()) {
        const QString note = setNote(t.service, d->set);
        const QString name = names.parameterName(d->address);
        return t.isWrite() ? TelegramText::tr("%1 reset to its default%2").arg(name, note)
                           : TelegramText::tr("%1 holds its default%2").arg(name, note);
    }
    if (const auto *d = t.as<ParameterLimits>())
        return TelegramText::tr("limits of %1: %2 .. %3")
            .arg(names.parameterName(d->address), names.number(d->address, d->lower),
                 names.number(d->address, d->upper));
    if (const auto *d = t.as<DefaultValue>())
        return TelegramText::tr("default of %1: %2")
            .arg(names.parameterName(d->address), names.value(d->address, d->value));
    if (const auto *d = t.as<PropertiesData>())
        return TelegramText::tr("properties of %1: %2, %3")
            .arg(names.parameterName(d->address), hexNumber(d->properties1, 8),
                 hexNumber(d->properties2, 8));
    if (const auto *d = t.as<DisplayScalingData>())
        return TelegramText::tr("display scaling of %1: divisor %2, multiplier %3, offset %4, "
                                "flags %5")
            .arg(names.parameterName(d->address))
            .arg(d->divisor)
            .arg(d->multiplier)
            .arg(d->offset)
            .arg(hexNumber(d->flags, 4));
    if (const auto *d = t.as<NameData>()) {
        const QString text = QString::fromLatin1(d->text);
        return t.service == Service::GroupName
            ? TelegramText::tr("name of group %1: \"%2\"").arg(names.groupName(d->address), text)
            : TelegramText::tr("name of %1: \"%2\"").arg(names.parameterName(d->address), text);
    }
    if (const auto *d = t.as<PlaintextIndicesData>())
        return TelegramText::tr("plaintext indices of %1: display %2 (%3), COMBIVIS %4 (%5)")
            .arg(names.parameterName(d->address))
            .arg(d->displayIndex)
            .arg(d->displayCount)
            .arg(d->combivisIndex)
            .arg(d->combivisCount);
    if (const auto *d = t.as<GroupPropertiesData>())
        return TelegramText::tr("group %1: id %2, order %3, highest number %4, count %5")
            .arg(names.groupName(d->address),
                 QString::fromLatin1(QByteArray(d->id.data(), 2)).trimmed())
            .arg(d->index)
            .arg(d->highestNumber)
            .arg(int(d->countMinusOne) + 1);
    if (const auto *d = t.as<CombivisPlaintextData>())
        return TelegramText::tr("plaintext %1.%2.%3: %4 = \"%5\"")
            .arg(d->index)
            .arg(d->definition)
            .arg(d->subindex)
            .arg(d->value)
            .arg(QString::fromLatin1(d->text));
    if (const auto *d = t.as<PlaintextDefinitionData>())
        return TelegramText::tr("plaintext definition %1.%2: mask %3, count %4, \"%5\"")
            .arg(d->index)
            .arg(d->definition)
            .arg(hexNumber(d->mask, 8))
            .arg(d->count)
            .arg(QString::fromLatin1(d->text));
    if (const auto *d = t.as<ScopeData>())
        return TelegramText::tr("scope at %1 ms: %2, %3, %4, %5")
            .arg(d->timestamp)
            .arg(d->wide[0])
            .arg(d->wide[1])
            .arg(d->narrow[0])
            .arg(d->narrow[1]);
    const QString numbers = numbersOf(t.data);
    const QString service = serviceName(t.service);
    return numbers.isEmpty() ? TelegramText::tr("%1: done").arg(service)
                             : TelegramText::tr("%1: %2").arg(service, numbers);
}

} // namespace

QString TelegramText::describe(const Telegram &telegram, const DriveDescription *drive,
                               const Telegram *request)
{
    const Namer names(drive);
    QString text;
    if (!telegram.isResponse()) {
        text = requestText(telegram, names);
        if (telegram.driveAddress >= 0)
            text = tr("to drive %1: %2").arg(telegram.driveAddress).arg(text);
    } else if (!request) {
        text = telegram.ack == Ack::Ok
            ? tr("answer to no open request: %1").arg(serviceName(telegram.service))
            : tr("answer to no open request: %1, %2")
                  .arg(serviceName(telegram.service), ackText(telegram.ack));
    } else if (telegram.ack != Ack::Ok) {
        text = tr("%1 refused: %2").arg(requestText(*request, names), ackText(telegram.ack));
    } else {
        text = answerText(telegram, names);
    }
    return text;
}

} // namespace DriveDesk
