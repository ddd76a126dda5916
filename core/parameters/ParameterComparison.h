#pragma once

#include "DriveDescription.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace DriveDesk {

// One difference between two descriptions of a drive (two parameter files, a drive and a file):
// a value of one set that differs, or a parameter only one side has. Values are in display
// form, each side formatted with its own metadata.
struct ParameterDifference
{
    enum class Kind : quint8 { Different, OnlyInA, OnlyInB };

    Kind kind = Kind::Different;
    quint16 address = 0;
    QString id;   // "op.11"
    QString name; // side A's, or B's where A lacks the parameter
    int set = -1; // the set of a differing value; -1 for a parameter only one side has
    QString a;    // "3000 1/min", "?" where that side did not read it, empty where it has none
    QString b;
};

struct ParameterComparison
{
    Q_DECLARE_TR_FUNCTIONS(ParameterComparison)
public:
    QList<ParameterDifference> differences; // by address, then set
    int compared = 0; // parameters both sides have

    bool isEqual() const { return differences.isEmpty(); }
    // "Different", "only in A", "only in B".
    static QString kindText(ParameterDifference::Kind kind);
};

// Compares every parameter value of `a` with `b`, set by set where either side holds one value
// per set. A value one side read and the other did not differs; two unread values do not.
ParameterComparison compareDescriptions(const DriveDescription &a, const DriveDescription &b);

// Compares the values a user sets (isUserSetting) with their defaults, set by set; the
// defaults are side B, or side A with `defaultsFirst`. Live values and counters are left out:
// they are no setting to go back to.
ParameterComparison compareWithDefaults(const DriveDescription &drive, bool defaultsFirst = false);

} // namespace DriveDesk
