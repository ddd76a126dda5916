#include "DriveState.h"

#include "F5Addresses.h"
#include "LiveSignals.h"
#include "Passwords.h"

#include <algorithm>

namespace DriveDesk::Sim {

namespace {

// Longer pauses than this are skipped: the motor keeps its state (the heat sink has settled
// after ten minutes anyway).
constexpr qint64 kMaxCatchUpMs = 600 * 1000;

// The demo cycle in fractions of its period: stand, forward, stop, reverse at 2/3 speed, stop.
struct DemoPhase
{
    double start;
    double speedFactor;
};
constexpr DemoPhase kDemoPhases[]
    = { { 0.0, 0 }, { 0.05, 1 }, { 0.40, 0 }, { 0.50, -2.0 / 3 }, { 0.85, 0 } };

qint64 demoPeriodMs(const DriveState &state)
{
    return std::max<qint64>(1000, qint64(state.setting(F5::kDemoPeriod, 200)) * 100);
}

bool demoRunning(const DriveState &state)
{
    return state.setting(F5::kSetValueSource, 1) == 1;
}

// The next moment after `t` at which the demo cycle changes its set value.
qint64 nextDemoChange(qint64 t, qint64 period)
{
    const qint64 cycleStart = t - t % period;
    for (int cycle = 0; cycle < 2; ++cycle) {
        for (const DemoPhase &phase : kDemoPhases) {
            const qint64 at = cycleStart + cycle * period + qint64(phase.start * double(period));
            if (at > t)
                return at;
        }
    }
    return t + period;
}

} // namespace

DriveState::DriveState(std::shared_ptr<const ParameterDatabase> db, int address, quint32 seed)
    : m_db(std::move(db))
    , m_address(address)
    , m_seed(seed)
    , m_passwordLevel(kPowerOnPasswordLevel)
{
    m_values.reserve(m_db->parameters().size());
    for (const SimParameter &p : m_db->parameters())
        m_values.push_back(p.initial);
    const int sy06 = m_db->indexOf(F5::kDriveAddress);
    if (sy06 >= 0)
        store(sy06, 0xFF, address);
}

int DriveState::activeSet() const
{
    return std::clamp(setting(F5::kActiveSet, 0), 0, kSets - 1);
}

int DriveState::setPointer() const
{
    const int index = m_db->indexOf(F5::kSetPointer);
    return index < 0 ? 0 : std::clamp(stored(index, 0), 0, kSets - 1);
}

qint32 DriveState::stored(int index, int set) const
{
    const SimParameter &p = m_db->parameters()[std::size_t(index)];
    return m_values[std::size_t(index)][p.isSetProgrammable() ? std::size_t(set) : 0];
}

void DriveState::store(int index, quint8 mask, qint32 value)
{
    auto &values = m_values[std::size_t(index)];
    if (!m_db->parameters()[std::size_t(index)].isSetProgrammable()) {
        values[0] = value;
        return;
    }
    for (int set = 0; set < kSets; ++set) {
        if (mask & (1u << set))
            values[std::size_t(set)] = value;
    }
}

qint32 DriveState::value(int index, int set) const
{
    const SimParameter &p = m_db->parameters()[std::size_t(index)];
    if (p.signal != LiveSignal::None)
        return liveValue(*this, p.signal, index);
    return stored(index, set);
}

qint32 DriveState::setting(quint16 address, qint32 fallback) const
{
    const int index = m_db->indexOf(address);
    if (index < 0)
        return fallback;
    // Fr.02 itself is not set-programmable, so this does not recurse.
    const SimParameter &p = m_db->parameters()[std::size_t(index)];
    return stored(index, p.isSetProgrammable() ? activeSet() : 0);
}

MotorSettings DriveState::motorSettings() const
{
    MotorSettings s;
    s.polePairs = std::max(1, setting(F5::kPolePairs, 2));
    const double hundredHertzRpm = 100.0 * 60 / s.polePairs;
    const double accelerationS = setting(F5::kAccelerationTime, 500) / 100.0;
    const double decelerationS = setting(F5::kDecelerationTime, 500) / 100.0;
    s.accelerationRpmPerS = accelerationS > 0 ? hundredHertzRpm / accelerationS : 0;
    s.decelerationRpmPerS = decelerationS > 0 ? hundredHertzRpm / decelerationS : 0;
    s.ratedSpeedRpm = setting(F5::kRatedSpeed, 1450);
    s.ratedFrequencyHz = setting(F5::kRatedFrequency, 500) / 10.0;
    s.ratedCurrentA = setting(F5::kRatedCurrent, 85) / 10.0;
    s.magnetisingCurrentA = std::min(s.ratedCurrentA, setting(F5::kMagnetisingCurrent, 32) / 10.0);
    s.ratedTorqueNm = setting(F5::kRatedTorque, 263) / 10.0;
    s.cornerFrequencyHz = setting(F5::kCornerFrequency, 500) / 10.0;
    s.cornerVoltageV = setting(F5::kCornerVoltage, 400);
    s.boostPercent = setting(F5::kBoost, 20) / 10.0;
    return s;
}

double DriveState::targetRpm(qint64 atMs) const
{
    double target = 0;
    if (demoRunning(*this)) {
        const qint64 period = demoPeriodMs(*this);
        const double phase = double(atMs % period) / double(period);
        double factor = 0;
        for (const DemoPhase &p : kDemoPhases) {
            if (phase >= p.start)
                factor = p.speedFactor;
        }
        target = factor * setting(F5::kDemoSpeed, 1500);
    } else {
        target = setting(F5::kCommandSpeed, 0);
    }
    if (target > 0)
        target = std::clamp<double>(target, setting(F5::kMinimumSpeedForward, 0),
                                    std::max(0, setting(F5::kMaximumSpeedForward, 3000)));
    else if (target < 0)
        target = -std::clamp<double>(-target, setting(F5::kMinimumSpeedReverse, 0),
                                     std::max(0, setting(F5::kMaximumSpeedReverse, 3000)));
    return target;
}

void DriveState::advanceTo(qint64 nowMs)
{
    if (!m_started) {
        m_started = true;
        m_firstMs = m_clockMs = nowMs;
        return;
    }
    if (nowMs <= m_clockMs)
        return;
    qint64 t = std::max(m_clockMs, nowMs - kMaxCatchUpMs);
    // Records are only kept for the last kRecordCount ticks: step finely only there.
    const qint64 fineFrom = nowMs - kRecordCount * kRecordPeriodMs;
    const bool demo = demoRunning(*this);
    const qint64 period = demoPeriodMs(*this);
    const MotorSettings settings = motorSettings();
    while (t < nowMs) {
        qint64 next = nowMs;
        if (demo)
            next = std::min(next, nextDemoChange(t, period));
        if (t + kRecordPeriodMs > fineFrom)
            next = std::min(next, (t / kRecordPeriodMs + 1) * kRecordPeriodMs);
        else // one step to where the records begin, not past them
            next = std::min(next, fineFrom / kRecordPeriodMs * kRecordPeriodMs);
        m_clockMs = next;
        m_motor.run(double(next - t) / 1000, targetRpm(t), settings);
        t = next;
        if (t % kRecordPeriodMs == 0 && t > fineFrom)
            recordSample();
    }
}

std::array<qint32, 4> DriveState::readChannels() const
{
    std::array<qint32, 4> values {};
    for (std::size_t channel = 0; channel < values.size(); ++channel) {
        const qint32 address = setting(F5::kReadChannel[channel], -1);
        const int index = address < 0 ? -1 : m_db->indexOf(quint16(address));
        if (index < 0)
            continue;
        const auto mask = quint32(setting(F5::kReadChannel[channel] + 1, 1));
        int set = 0;
        while (set < kSets - 1 && !(mask & (1u << set)))
            ++set;
        values[channel] = value(index, set);
    }
    return values;
}

void DriveState::recordSample()
{
    ScopeRecord &record = m_records[std::size_t(m_recordHead)];
    record.timestamp = quint16(m_clockMs & 0xFFFF);
    record.values = readChannels();
    m_recordHead = (m_recordHead + 1) % kRecordCount;
    m_recordCount = std::min(m_recordCount + 1, kRecordCount);
}

const ScopeRecord &DriveState::record(int index) const
{
    const int oldest = (m_recordHead - m_recordCount + kRecordCount) % kRecordCount;
    return m_records[std::size_t((oldest + index) % kRecordCount)];
}

} // namespace DriveDesk::Sim
