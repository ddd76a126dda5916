#pragma once

#include "DriveDescription.h"

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace DriveDesk {

// Where the metadata of two descriptions first part: a group or parameter only one side has,
// or the first field of one parameter (or group) in which they differ, with the field's value
// on each side as that side shows it.
struct MetadataDifference {
    enum class Presence : quint8 { Both, OnlyInA, OnlyInB };

    bool isGroup = false;
    QString id;    // "op.28", or the group's id
    QString name;  // the parameter's (or group's) name on the side that has it, A's for both
    Presence presence = Presence::Both;
    QString field; // "upper limit", "properties 1", ...: where both have it
    QString a;
    QString b;
};

// The rule that makes a drive with no identification (no identification parameters whose
// values name its kind, DriveIdentity::kind()) the same kind as a file or another drive: the
// same groups (page, id, name) and the same parameters of the parameter list, each with the
// same name, properties, display scaling and limits. What the properties say a drive works out
// afresh (variable limits, bits 12-15; variable scaling, bit 31) is not compared; neither are
// defaults, plaintexts and values. Names are compared as read, so both sides must be in one
// language.
class MetadataMatch
{
    Q_DECLARE_TR_FUNCTIONS(MetadataMatch)
public:
    enum class Scope : quint8 {
        Whole,      // every group and parameter on either side
        AHoldsPart, // A may lack groups and parameters B has (a selection of values)
    };

    // Nothing when the metadata is the same.
    static std::optional<MetadataDifference> firstDifference(const DriveDescription &a,
                                                             const DriveDescription &b,
                                                             Scope scope = Scope::Whole);

    // The difference as a download or a check names it, A being the file and B the drive:
    // "op.28 Ramp time: upper limit is 10.00 s in the file, 5.00 s on the drive".
    static QString text(const MetadataDifference &difference);
};

} // namespace DriveDesk
