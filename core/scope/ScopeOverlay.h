#pragma once

#include "ScopeRecording.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <memory>

namespace DriveDesk {

// Where an overlay's time axis is pinned to the recording shown.
enum class ScopeOverlayAlignment {
    Trigger, // the overlay's trigger on the shown recording's trigger
    Start, // the overlay's first sample on the shown recording's first sample
};

// How an overlay lies on the shown recording's time axis.
struct ScopeOverlayShift
{
    // Added to an overlay sample's time (its recording's ms), it gives the shown recording's ms.
    qint64 shiftMs = 0;
    // The alignment applied: Start where Trigger was wanted but a trigger is missing.
    ScopeOverlayAlignment alignment = ScopeOverlayAlignment::Start;
    // Why the trigger could not be used ("the overlay has no trigger"); empty where it was,
    // or where the start was wanted.
    QString fallback;
    bool operator==(const ScopeOverlayShift &) const = default;
};

// A second recording, read from a file, drawn over the one shown to compare them (a tuning run
// against an earlier one): its samples and min/max levels as any recording's, the file it came
// from, and where it lies on the shown recording's time axis (shiftTo()). Read-only once
// loaded, so it may be shared with another thread.
class ScopeOverlay
{
    Q_DECLARE_TR_FUNCTIONS(ScopeOverlay)
public:
    // Reads a recording file (readScopeFile()); in any thread, e.g. the thread pool for a large
    // one. On failure isLoaded() is false and error() says why, naming the file.
    static ScopeOverlay load(const QString &path);

    bool isLoaded() const { return m_recording != nullptr; }
    QString error() const { return m_error; }
    // What was left out of a file cut short (readScopeFile()'s warnings).
    QStringList warnings() const { return m_warnings; }
    const ScopeRecording &recording() const { return *m_recording; }
    QString path() const { return m_path; }
    // "run2.ddscope": how the legend and the cursors' read-out name it.
    QString fileName() const;
    // A channel's title as the overlay's, for the legend and the cursors' read-out (the unit
    // follows): "ru.03 Actual frequency (overlay: run2.ddscope)".
    QString label(const QString &title) const;

    // The rule that puts the overlay on `shown`'s time axis: at the triggers, both single
    // shots' (ScopeRecording::triggerMs), or at the first samples. Trigger falls back to
    // Start, saying why, where either recording has no trigger.
    ScopeOverlayShift shiftTo(const ScopeRecording &shown, ScopeOverlayAlignment wanted) const;

private:
    std::shared_ptr<const ScopeRecording> m_recording;
    QString m_path;
    QString m_error;
    QStringList m_warnings;
};

} // namespace DriveDesk
