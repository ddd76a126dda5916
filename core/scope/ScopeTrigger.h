#pragma once

#include <QtGlobal>

namespace DriveDesk {

struct ScopeRecording;

// What a single-shot trigger waits for, and how long a shot it takes.
struct ScopeTriggerSettings
{
    enum class Edge { Rising, Falling };

    int channel = 0; // 0..3
    double level = 0.0; // in the channel's display units (ScopeChannel::toDisplay())
    Edge edge = Edge::Rising;
    double preTriggerShare = 0.2; // the part of the shot before the trigger, 0..1
    qint64 windowMs = 1000; // the shot's length, at least 1

    // share * window, rounded to whole ms.
    qint64 preTriggerMs() const;
    qint64 postTriggerMs() const { return windowMs - preTriggerMs(); }
    bool operator==(const ScopeTriggerSettings &) const = default;
};

// A single-shot trigger, as a drive maker's trace tool has one (docs/scope.md, "The trigger"):
// armed at a sample, it first lets the pre-trigger time be recorded, then fires at the first
// sample that crosses the level on the chosen edge; the shot is the window around that sample
// and is complete once its end has been recorded.
//
// Fed as the recording grows: update() scans only the samples appended since the last call, so
// feeding it in any batches gives the same result as feeding it all at once. Single-threaded,
// like the recording.
class ScopeTrigger
{
public:
    enum class State {
        Idle, // not armed
        Armed, // waiting for the pre-trigger time, then for the edge
        Triggered, // fired: the shot's range is known, its end not yet recorded
        Complete, // the shot's end has been recorded
    };

    explicit ScopeTrigger(const ScopeTriggerSettings &settings = {});

    // Out-of-range values are brought into range (channel 0..3, share 0..1, window >= 1 ms).
    // Changing the settings disarms.
    void setSettings(const ScopeTriggerSettings &settings);
    const ScopeTriggerSettings &settings() const { return m_settings; }

    // Watches the recording's samples from index `fromIndex` on: usually the buffer's count()
    // when the user arms, so the first sample to arrive afterwards starts the pre-trigger time.
    // After the recording's buffer is cleared, arm again.
    void arm(qsizetype fromIndex);
    void disarm();

    // Looks at the samples appended since the last call; returns the new state.
    State update(const ScopeRecording &recording);
    State state() const { return m_state; }

    // Once Triggered: the sample that fired, and its time.
    qsizetype triggerIndex() const { return m_triggerIndex; }
    qint64 triggerTime() const { return m_triggerTime; }
    // Once Triggered: the shot, [triggerTime - pre, triggerTime + post] in the recording's ms.
    qint64 shotStart() const { return m_triggerTime - m_settings.preTriggerMs(); }
    qint64 shotEnd() const { return m_triggerTime + m_settings.postTriggerMs(); }

private:
    void search(const ScopeRecording &recording);
    bool crosses(double before, double now) const;

    ScopeTriggerSettings m_settings;
    State m_state = State::Idle;
    qsizetype m_armedIndex = 0; // the first sample watched
    qsizetype m_next = 0; // the first sample not yet looked at
    qsizetype m_triggerIndex = -1;
    qint64 m_triggerTime = 0;
};

} // namespace DriveDesk
