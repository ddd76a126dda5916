#pragma once

#include "DriveDescription.h"
#include "ParameterComparison.h"

#include <QCoreApplication>
#include <QList>
#include <QStringList>

namespace DriveDesk {

// One value a user chose in the compare view to write into one side: the other side's raw value
// for a set of the side written. Set 0 for a parameter with one value.
struct ChosenValue
{
    quint16 address = 0;
    int set = 0;
    qint32 raw = 0;
    bool operator==(const ChosenValue &) const = default;
};

// Writing the values chosen in a comparison into one of its sides: a parameter file directly, a
// drive through a download of a selection.
class ChosenValues
{
    Q_DECLARE_TR_FUNCTIONS(ChosenValues)
public:
    // The values the chosen rows write into side A (`toA`) or B: the other side's raw value for
    // the written side's set, from the rows that may be written that way
    // (ComparisonRow::isWritableTo); the others are left out.
    static QList<ChosenValue> from(const QList<ComparisonRow> &chosen, bool toA);

    // Puts the values into `target` (a parameter file's description). A value is refused, with
    // the reason in `refusals`, where `target` lacks the parameter, where a download would not
    // write it (ParameterList::isWrittenByDownload) or where it lies outside the target's
    // limits. How many values were put in.
    static int apply(DriveDescription &target, const QList<ChosenValue> &values,
                     QStringList *refusals = nullptr);

    // What a download writes to a drive for the chosen values: `source` (the description of the
    // side the values come from: its groups, metadata and identification) with each chosen
    // (parameter, set) holding the chosen value and every other value empty (std::nullopt),
    // except the identification parameters (DriveIdentity::parameters()), which keep their
    // values so that the download can check the kind of drive. A chosen value of a parameter
    // `source` lacks is left out.
    static DriveDescription selectionFor(const DriveDescription &source,
                                         const QList<ChosenValue> &values);
};

} // namespace DriveDesk
