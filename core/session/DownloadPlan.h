#pragma once

#include "parameters/DriveDescription.h"
#include "session/ValueChange.h"
#include "session/WriteChangesJob.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

#include <array>
#include <optional>

namespace DriveDesk {

struct DownloadOptions
{
    quint8 sets = 0xFF; // the sets whose values are written (--sets)
    bool force = false; // write although the checks found problems
    // The file holds only values chosen to be written (a compare view's selection): the
    // drive's parameters and values it lacks are left as they are, not missing.
    bool selection = false;
    // The job the download's writes are journaled as; empty: the download of its file. A
    // revert of journal entries names itself ("revert of entries 12..15", JournalRevertPlan).
    QString journalJob;
};

// One parameter a download writes: its values, grouped into one step per value.
struct DownloadItem
{
    QString id;   // "op.11"
    QString name; // the drive's
    ValueChange change;
    // What the file holds, per set written ([0] for a value that is not per set), and what the
    // drive held before.
    std::array<std::optional<qint32>, kParameterSets> wanted{};
    std::array<std::optional<qint32>, kParameterSets> before{};
    bool always = false; // written whatever the drive holds (write always, write only)
    // What its writes wait for and hold up: a selector changes what later writes mean, a
    // variable limit follows from what was written before it. Free of both by default.
    WriteOrder order{false, false};
};

// A parameter, or some of its sets, that the download leaves although the file holds another
// value than the drive.
struct DownloadSkip
{
    QString id;
    QString name;
    QString reason; // in words: "read-only", "set 3 is not in the file"
};

// What downloading a parameter file to a drive writes, worked out before anything is sent:
// the checks that refuse it, the values that differ (and those always written) in the order
// they are written, and what is left. docs/parameter-file.md says why in this order.
struct DownloadPlan
{
    Q_DECLARE_TR_FUNCTIONS(DownloadPlan)
public:
    // Why the download is refused unless forced: another kind of drive or software version,
    // parameters only one side has, values outside the drive's limits.
    QStringList problems;
    bool forced = false;
    QList<DownloadItem> items;
    QList<DownloadSkip> skipped;
    int unchanged = 0; // values (parameter and set) the drive already holds
    int readOnlyDiffering = 0; // read-only values that differ: never written, not listed

    // One value (or several sets taking one value) to write, in display form.
    struct Line
    {
        QString id;
        QString name;
        QString sets;  // "sets 0, 2", empty for a parameter that holds one value
        QString now;   // what the drive holds ("not read" for a write-only value)
        QString then;  // what the file holds
        bool always = false;
    };

    bool isRefused() const { return !problems.isEmpty() && !forced; }
    int valueCount() const; // values the items write
    // For --dry-run and the window's last look: every value to write, drive's and file's.
    QList<Line> lines(const DriveDescription &drive) const;
    QString text(const DriveDescription &drive) const;
    // "3 values to write, 640 unchanged, 1 left; 2 read-only values differ and are never
    // written".
    QString summary() const;
};

// Whether `file` was made for the kind of drive `drive` is (its identification parameters, or
// its metadata where it has none), as the download refuses and a plant's verify judges: empty
// when it was, else each reason it was not. `selection`: the file holds part of a drive.
QStringList kindProblems(const DriveDescription &file, const DriveDescription &drive,
                         bool selection = false);

// `drive` is a scan of the drive with its values; `file` a parameter file.
DownloadPlan planDownload(const DriveDescription &file, const DriveDescription &drive,
                          const DownloadOptions &options);

} // namespace DriveDesk
