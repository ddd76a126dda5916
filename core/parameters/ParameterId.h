#pragma once

#include "DriveDescription.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// A group a drive has: its id ("ru") and first address (0200h; half-page groups 0280h).
struct GroupAddress
{
    QString id;
    quint16 address = 0;
    bool operator==(const GroupAddress &) const = default;
};

// The ids users type and read for parameter addresses: "ru.03" for 0203h given group ru at
// 0200h, "0203h" where no known group holds the address. A parameter's number counts from its
// group's first address, so a half-page group Fb at 0280h has Fb.09 = 0289h.
class ParameterId
{
    Q_DECLARE_TR_FUNCTIONS(ParameterId)
public:
    static QList<GroupAddress> groupsOf(const DriveDescription &drive);

    // "ru.3", "ru.03", "ru03", "RU.3" (the group id matched case-insensitively where that is
    // unique), "0x0203", "0203h". Hexadecimal addresses need no known group.
    static std::optional<quint16> parse(const QString &text, const QList<GroupAddress> &groups,
                                        QString *error = nullptr);
    static std::optional<quint16> parse(const QString &text, const DriveDescription &drive,
                                        QString *error = nullptr);
    // Whether `text` has the form parse() takes, whatever groups a drive has: what a file
    // naming parameters for drives not yet seen can check.
    static bool isWellFormed(const QString &text);

    // The id messages and the parameter table name a parameter by: "op.11", or "0203h".
    static QString format(quint16 address, const GroupAddress &group);
    static QString format(quint16 address, const QList<GroupAddress> &groups);
    static QString format(quint16 address, const DriveDescription &drive);
    static QString hexAddress(quint16 address); // "0203h"

    // The group holding the address: the one with the highest first address at or below it
    // within the same high byte. Nothing when none does.
    static std::optional<GroupAddress> groupOf(quint16 address, const QList<GroupAddress> &groups);
    // How many numbers the group spans: up to the next group in its page or the page end.
    static int numberLimit(const GroupAddress &group, const QList<GroupAddress> &groups);
};

} // namespace DriveDesk
