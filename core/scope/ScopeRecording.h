#pragma once

#include "ScopeBuffer.h"
#include "ScopeChannel.h"
#include "ScopeMathDefinition.h"

#include <QDateTime>
#include <QString>

#include <memory>
#include <optional>

namespace DriveDesk {

// One scope recording: its samples with their min/max levels, what each channel carries, and
// where and when it was taken. What the chart shows, the CSV and the recording file hold.
// Single-threaded (see SampleStore).
struct ScopeRecording
{
    ScopeRecording();

    ScopeBuffer buffer;
    ScopeChannels channels; // ScopeSample::kChannelCount entries
    QDateTime started;      // the host's clock at the first sample, UTC
    QString source;         // the connection ("HSP5 on /dev/ttyUSB0"), or the file it came from
    // The math channels the user added: definitions only, their values follow from the samples
    // (computeScopeMath()). Kept with the recording in its file; never sent to a drive.
    QList<ScopeMathDefinition> math;
    // Where a single shot fired, in the recording's ms; none for a recording that is no shot.
    // Kept in its file: an overlay is aligned at it (ScopeOverlay).
    std::optional<qint64> triggerMs;

    // The samples' first and last time in ms; 0 and 0 when there are none.
    qint64 firstTime() const;
    qint64 lastTime() const;
    // The channels worth showing and exporting: those the drive delivers, or all four where it
    // delivers none (offline records taken under an assignment that has changed since).
    QList<int> recordedChannels() const;
    // The samples from fromMs to toMs, both included, as a recording of their own: the same
    // channels and source, `started` moved on by the time left out before them. A single shot
    // keeps its window of the wait for the trigger this way; the trigger stays where it is
    // inside the part.
    std::unique_ptr<ScopeRecording> excerpt(qint64 fromMs, qint64 toMs) const;
    // The display number of sample `index` on `channel`.
    double displayValue(qsizetype index, int channel) const
    {
        return channels.at(channel).toDisplay(buffer.samples().value(index, channel));
    }
};

} // namespace DriveDesk
