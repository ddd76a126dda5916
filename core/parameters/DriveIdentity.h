#pragma once

#include "DriveDescription.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// One identification parameter of a drive and what it says about the drive.
struct IdentificationParameter {
    const char *group;  // group id, e.g. "In"
    quint8 number;      // parameter number in the group
    bool namesTheKind;  // part of what makes two drives the same kind (not the serial number)
};

// The parameter value that, with the others of a DriveKind, says what kind of drive it is.
struct KindValue {
    quint16 address = 0;
    qint32 value = 0;
    bool operator==(const KindValue &) const = default;
};

// What makes two drives the same kind for their metadata: the values of the identification
// parameters that name the inverter type, the power unit and the software (not the serial
// number). Two drives of one kind have the same groups, parameters, limits and texts.
struct DriveKind {
    QList<KindValue> values; // by address

    QList<quint16> addresses() const;
    bool operator==(const DriveKind &) const = default;
};

// The identification every drive has in its parameters (on an F5 the Sy and In groups: inverter
// identifier, power unit, type, ratings, software version and date, serial number), where the
// scan found them. Seed 000 has no identification service, so this is what identifies a drive
// over HSP5; service 13 adds its text only where the protocol can carry it.
class DriveIdentity
{
    Q_DECLARE_TR_FUNCTIONS(DriveIdentity)
public:
    // The identification parameters in the order they are shown.
    static const QList<IdentificationParameter> &parameters();

    // The kind of drive the description shows, or nothing when a parameter that names the kind
    // is missing or was not read: such a drive cannot be told apart from another.
    static std::optional<DriveKind> kind(const DriveDescription &drive);

    // "ru.03 = value" lines for a user: each identification parameter the drive has, with its
    // name and its value as the drive shows it.
    struct Line {
        QString label; // "Software version (In.06)"
        QString value; // "1.80", or why it was not read
    };
    static QList<Line> lines(const DriveDescription &drive);

    // One line naming the drive: the service 13 text where the drive gave one, otherwise its
    // type, software version and serial number from the identification parameters; empty when
    // the drive has neither.
    static QString summary(const DriveDescription &drive);
    // An identification parameter's value as the drive shows it ("1.82"); empty where the
    // drive lacks it or it was not read.
    static QString shown(const DriveDescription &drive, const char *group, quint8 number);
};

} // namespace DriveDesk
