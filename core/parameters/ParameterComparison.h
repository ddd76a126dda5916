#pragma once

#include "DriveDescription.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// Whether a parameter counts as a setting when two descriptions are compared: a value the user
// sets (isUserSetting: not read-only, not live, not changed by the drive itself) whose value an
// upload reads (ParameterList::isReadByUpload: not excluded from the list, not write only). The
// one rule of compareDescriptions(), compareAll() and compareSets(), so of `diff`, the compare
// window and a check that a drive still matches its backup: anything else may be shown, never
// counted.
bool countsAsSetting(const ParameterDescription &parameter);

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

// Compares every setting (countsAsSetting) of `a` with `b`, set by set where either side holds
// one value per set. A value one side read and the other did not differs; two unread values do
// not. Live and read-only values and parameters a parameter list leaves out are no difference.
ParameterComparison compareDescriptions(const DriveDescription &a, const DriveDescription &b);

// Compares the values a user sets (isUserSetting) with their defaults, set by set; the
// defaults are side B, or side A with `defaultsFirst`. Live values and counters are left out:
// they are no setting to go back to.
ParameterComparison compareWithDefaults(const DriveDescription &drive, bool defaultsFirst = false);

// The settings (countsAsSetting) of `drive`, as they are: the parameters compareWithDefaults()
// looks at.
DriveDescription userSettingsOf(const DriveDescription &drive);
// The same parameters as userSettingsOf(), each with its default in every set it has.
DriveDescription defaultsOf(const DriveDescription &drive);

// One row of the compare view: a parameter's value in one set on both sides, in display form
// and raw. The state says what a user may do about it.
struct ComparisonRow
{
    enum class State : quint8 {
        Equal,
        Different,
        OnlyInA,
        OnlyInB,
        // On both sides, and a download would not write it (ParameterList::isWrittenByDownload
        // is false by either side's metadata: read-only, live or changed by the drive, left out
        // of transfer lists). Neither side can be made like the other; `differs` tells whether
        // the values do.
        ReadOnly,
        // Not a setting by the metadata of a side that has it (countsAsSetting is false): a live
        // or read-only value, or one a parameter list leaves out. Shown on request, never a
        // difference; `differs` tells whether the values do.
        NotASetting,
    };

    State state = State::Equal;
    bool differs = false; // the values differ (always for a parameter only one side has)
    quint16 address = 0;
    QString id;      // "oP.10"
    QString name;    // side A's, or B's where A lacks the parameter
    QString groupId; // "oP"
    // The set of each side's value; 0 for a parameter with one value. The same on both sides
    // unless one set is compared with another.
    int setA = 0;
    int setB = 0;
    bool perSet = false; // either side holds one value per set
    std::optional<qint32> rawA;
    std::optional<qint32> rawB;
    QString a; // "50.00 Hz", "?" where that side did not read it, empty where it has none
    QString b;
    // Only one side has the parameter; the state may still be NotASetting.
    bool onlyInA = false;
    bool onlyInB = false;

    // A value of the other side can be written into this one: the values differ, both sides
    // have the parameter, a download may write it, and the other side's value is known.
    bool isWritableTo(bool toA) const
    {
        return state == State::Different && (toA ? rawB : rawA).has_value();
    }
};

// Every row of a comparison for a view, by address, then set.
struct ComparisonTable
{
    Q_DECLARE_TR_FUNCTIONS(ComparisonTable)
public:
    QList<ComparisonRow> rows;

    int count(ComparisonRow::State state) const;
    // "equal", "different", "only in A", "only in B", "read-only", "not a setting".
    static QString stateText(ComparisonRow::State state);
};

// Every parameter of `a` and `b` by address, set by set where either side holds one value per
// set; a parameter only one side has is listed set by set as that side holds it. Two unread
// values are equal, as in compareDescriptions().
ComparisonTable compareAll(const DriveDescription &a, const DriveDescription &b);

// Set `setA` of `a` against set `setB` of `b` (one description against itself for two sets of
// one drive or file): the parameters that either side holds per set. A parameter with one value
// is the same in every set and left out.
ComparisonTable compareSets(const DriveDescription &a, int setA, const DriveDescription &b,
                            int setB);

} // namespace DriveDesk
