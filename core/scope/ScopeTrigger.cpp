#include "ScopeTrigger.h"

#include "ScopeRecording.h"

#include <algorithm>

namespace DriveDesk {

qint64 ScopeTriggerSettings::preTriggerMs() const
{
    return qRound64(preTriggerShare * double(windowMs));
}

ScopeTrigger::ScopeTrigger(const ScopeTriggerSettings &settings)
{
    setSettings(settings);
}

void ScopeTrigger::setSettings(const ScopeTriggerSettings &settings)
{
    m_settings = settings;
    m_settings.channel = qBound(0, settings.channel, ScopeSample::kChannelCount - 1);
    m_settings.preTriggerShare = qBound(0.0, settings.preTriggerShare, 1.0);
    m_settings.windowMs = qMax<qint64>(1, settings.windowMs);
    disarm();
}

void ScopeTrigger::arm(qsizetype fromIndex)
{
    m_state = State::Armed;
    m_armedIndex = qMax<qsizetype>(0, fromIndex);
    m_next = m_armedIndex;
    m_triggerIndex = -1;
    m_triggerTime = 0;
}

void ScopeTrigger::disarm()
{
    m_state = State::Idle;
    m_triggerIndex = -1;
    m_triggerTime = 0;
}

ScopeTrigger::State ScopeTrigger::update(const ScopeRecording &recording)
{
    const SampleStore &samples = recording.buffer.samples();
    // Fewer samples than seen: the buffer was cleared under us; wait to be armed again.
    if (samples.count() < m_next)
        return m_state;
    if (m_state == State::Armed)
        search(recording);
    if (m_state == State::Triggered && samples.time(samples.count() - 1) >= shotEnd())
        m_state = State::Complete;
    return m_state;
}

void ScopeTrigger::search(const ScopeRecording &recording)
{
    const SampleStore &samples = recording.buffer.samples();
    const qsizetype count = samples.count();
    if (count <= m_armedIndex)
        return; // the first watched sample has not come yet
    // The sample before the crossing must be watched too, so the earliest to fire is the
    // second; and none fires before the pre-trigger time has been recorded since arming, so
    // that the shot never starts before the first watched sample.
    const qint64 armedAt = samples.time(m_armedIndex);
    qsizetype index = std::max(
        { m_next, m_armedIndex + 1, samples.lowerBound(armedAt + m_settings.preTriggerMs()) });
    const int channel = m_settings.channel;
    for (; index < count; ++index) {
        if (crosses(recording.displayValue(index - 1, channel),
                    recording.displayValue(index, channel))) {
            m_state = State::Triggered;
            m_triggerIndex = index;
            m_triggerTime = samples.time(index);
            m_next = index + 1;
            return;
        }
    }
    m_next = count;
}

bool ScopeTrigger::crosses(double before, double now) const
{
    const double level = m_settings.level;
    if (m_settings.edge == ScopeTriggerSettings::Edge::Rising)
        return before < level && now >= level;
    return before > level && now <= level;
}

} // namespace DriveDesk
