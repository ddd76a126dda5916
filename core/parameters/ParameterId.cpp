#include "ParameterId.h"

#include <QRegularExpression>

namespace DriveDesk {

namespace {

// "0x0203", "0203h"
const QRegularExpression &hexPattern()
{
    static const QRegularExpression pattern(
        QStringLiteral("^(?:0[xX]([0-9A-Fa-f]+)|([0-9A-Fa-f]+)[hH])$"));
    return pattern;
}

// "ru.03", or without the dot ("ru03") where the group id is letters only.
const QRegularExpression &idPattern()
{
    static const QRegularExpression pattern(
        QStringLiteral("^(?:([^.\\s]+)\\.|([A-Za-z]+))([0-9]+)$"));
    return pattern;
}

} // namespace

bool ParameterId::isWellFormed(const QString &text)
{
    const QString trimmed = text.trimmed();
    return hexPattern().match(trimmed).hasMatch() || idPattern().match(trimmed).hasMatch();
}

QList<GroupAddress> ParameterId::groupsOf(const DriveDescription &drive)
{
    QList<GroupAddress> groups;
    groups.reserve(drive.groups.size());
    for (const GroupDescription &group : drive.groups)
        groups.append({ group.id, group.address });
    return groups;
}

QString ParameterId::hexAddress(quint16 address)
{
    return QString::number(address, 16).toUpper().rightJustified(4, QLatin1Char('0'))
        + QLatin1Char('h');
}

std::optional<GroupAddress> ParameterId::groupOf(quint16 address, const QList<GroupAddress> &groups)
{
    std::optional<GroupAddress> best;
    for (const GroupAddress &group : groups) {
        if ((group.address & 0xFF00) != (address & 0xFF00) || group.address > address)
            continue;
        if (!best || group.address > best->address)
            best = group;
    }
    return best;
}

int ParameterId::numberLimit(const GroupAddress &group, const QList<GroupAddress> &groups)
{
    int end = (group.address & 0xFF00) + 0x100;
    for (const GroupAddress &other : groups) {
        if ((other.address & 0xFF00) == (group.address & 0xFF00) && other.address > group.address)
            end = qMin(end, int(other.address));
    }
    return end - group.address;
}

QString ParameterId::format(quint16 address, const GroupAddress &group)
{
    return format(address, QList<GroupAddress> { group });
}

QString ParameterId::format(quint16 address, const QList<GroupAddress> &groups)
{
    const std::optional<GroupAddress> group = groupOf(address, groups);
    if (!group || group->id.isEmpty())
        return hexAddress(address);
    return parameterId(group->id, quint8(address - group->address));
}

QString ParameterId::format(quint16 address, const DriveDescription &drive)
{
    return format(address, groupsOf(drive));
}

std::optional<quint16> ParameterId::parse(const QString &input, const QList<GroupAddress> &groups,
                                          QString *error)
{
    auto fail = [error](const QString &message) -> std::optional<quint16> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QString text = input.trimmed();
    if (text.isEmpty())
        return fail(tr("no parameter given"));

    const QRegularExpressionMatch hex = hexPattern().match(text);
    if (hex.hasMatch()) {
        QString digits = hex.captured(1).isEmpty() ? hex.captured(2) : hex.captured(1);
        while (digits.size() > 1 && digits.startsWith(QLatin1Char('0')))
            digits.remove(0, 1);
        const uint address = digits.size() <= 8 ? digits.toUInt(nullptr, 16) : 0x10000;
        if (address > 0xFFFF)
            return fail(tr("'%1': address above FFFFh").arg(text));
        return quint16(address);
    }

    const QRegularExpressionMatch id = idPattern().match(text);
    if (!id.hasMatch()) {
        return fail(tr("'%1' is not a parameter id: write it as group.number (ru.03, ru03) or "
                       "as a hexadecimal address (0203h, 0x0203)")
                        .arg(text));
    }
    const QString groupId = id.captured(1).isEmpty() ? id.captured(2) : id.captured(1);
    std::optional<GroupAddress> group;
    QList<GroupAddress> caseInsensitive;
    for (const GroupAddress &candidate : groups) {
        if (candidate.id == groupId) {
            group = candidate;
            break;
        }
        if (candidate.id.compare(groupId, Qt::CaseInsensitive) == 0)
            caseInsensitive << candidate;
    }
    if (!group && caseInsensitive.size() > 1) {
        return fail(tr("'%1': the group id is ambiguous ('%2' or '%3'); write it with its case")
                        .arg(text, caseInsensitive.at(0).id, caseInsensitive.at(1).id));
    }
    if (!group && caseInsensitive.size() == 1)
        group = caseInsensitive.first();
    if (!group)
        return fail(tr("no group '%1' on this drive").arg(groupId));

    QString numberText = id.captured(3);
    while (numberText.size() > 1 && numberText.startsWith(QLatin1Char('0')))
        numberText.remove(0, 1);
    bool ok = false;
    const int number = numberText.size() <= 4 ? numberText.toInt(&ok) : 1 << 16;
    if (!ok || number > 255)
        return fail(tr("'%1': parameter number above 255").arg(text));
    const int limit = numberLimit(*group, groups);
    if (number >= limit) {
        return fail(tr("'%1': parameter number above %2 in group %3")
                        .arg(text)
                        .arg(limit - 1)
                        .arg(group->id));
    }
    return quint16(group->address + number);
}

std::optional<quint16> ParameterId::parse(const QString &text, const DriveDescription &drive,
                                          QString *error)
{
    return parse(text, groupsOf(drive), error);
}

} // namespace DriveDesk
