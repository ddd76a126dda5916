#include "LiveSignals.h"

#include "DriveState.h"
#include "F5Addresses.h"

#include <cmath>

namespace DriveDesk::Sim {

namespace {

constexpr double kPi = 3.141592653589793;
constexpr qint32 kOperatingHoursAtStart = 12345; // 0.1 h: the simulated drive is not new
constexpr qint32 kModulationHoursAtStart = 8765;

quint64 splitMix(quint64 x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

qint32 rounded(double value)
{
    return qint32(std::lround(value));
}

qint32 statusLow(const DriveState &state)
{
    const MotorModel &m = state.motor();
    qint32 word = 0;
    if (m.speedRpm() != 0 || m.targetRpm() != 0)
        word |= 1 << 0; // control release
    if (m.speedRpm() != 0)
        word |= 1 << 2; // run
    if (m.speedRpm() < 0 || (m.speedRpm() == 0 && m.targetRpm() < 0))
        word |= 1 << 3; // reverse
    word |= state.activeSet() << 4;
    return word;
}

// do.00..do.03 conditions evaluated (plaintexts "docond"), do.10 inverts.
qint32 outputState(const DriveState &state)
{
    const MotorModel &m = state.motor();
    const int code = m.stateCode();
    qint32 bits = 0;
    for (std::size_t output = 0; output < F5::kOutputCondition.size(); ++output) {
        bool on = false;
        switch (state.setting(F5::kOutputCondition[output], 0)) {
        case 1:
            on = true;
            break;
        case 2:
            on = m.speedRpm() != 0;
            break;
        case 3:
            on = true;
            break; // ready: the simulated drive has no errors
        case 5:
            on = code == 66 || code == 69;
            break;
        case 6:
            on = code == 64 || code == 67;
            break;
        case 7:
            on = code == 65 || code == 68;
            break;
        default:
            break;
        }
        if (on)
            bits |= 1 << output;
    }
    return (bits ^ state.setting(F5::kOutputInversion, 0)) & 0xFF;
}

qint32 inputState(const DriveState &state)
{
    return state.setting(F5::kSoftwareInputs, 0) & 0xFFF;
}

} // namespace

double measurementNoise(quint32 seed, quint32 channel, qint64 timeMs)
{
    const quint64 hash = splitMix(quint64(seed) << 40 ^ quint64(channel) << 32 ^ quint64(timeMs));
    return double(hash >> 11) / double(1ull << 53) * 2 - 1;
}

qint32 liveValue(const DriveState &state, LiveSignal signal, int index)
{
    const MotorModel &m = state.motor();
    const qint64 t = state.clockMs();
    const auto noise = [&](quint32 channel) { return measurementNoise(state.seed(), channel, t); };
    const auto readings = [&] { return m.readings(state.motorSettings()); };
    switch (signal) {
    case LiveSignal::None:
        return state.stored(index, 0);
    case LiveSignal::State:
        return m.stateCode();
    case LiveSignal::SetFrequency:
        return rounded(readings().setFrequencyHz * 80);
    case LiveSignal::ActualFrequency:
        return rounded(readings().outputFrequencyHz * 80);
    case LiveSignal::SetSpeed:
        return rounded(m.targetRpm());
    case LiveSignal::ActualSpeed: {
        const MotorReadings r = readings();
        return rounded((r.shaftSpeedRpm + (r.modulating ? noise(1) * 0.5 : 0)) * 8);
    }
    case LiveSignal::OutputVoltage:
        return rounded(readings().outputVoltageV);
    case LiveSignal::OutputPower:
        return rounded(readings().powerKw * 100);
    case LiveSignal::TorqueSet:
        return rounded(readings().torqueNm * 10);
    case LiveSignal::ActualTorque: {
        const MotorReadings r = readings();
        return rounded((r.torqueNm + (r.modulating ? noise(2) * 0.2 : 0)) * 10);
    }
    case LiveSignal::Load:
        return rounded(std::abs(readings().torqueNm)
                       / std::max(0.1, state.motorSettings().ratedTorqueNm) * 100);
    case LiveSignal::ApparentCurrent: {
        const MotorReadings r = readings();
        return r.modulating ? std::max(0, rounded((r.currentA + noise(3) * 0.05) * 10)) : 0;
    }
    case LiveSignal::PeakCurrent:
        return rounded(m.peakCurrentA() * 10);
    case LiveSignal::DcVoltage: {
        // 300 Hz ripple of the six-pulse rectifier, sampled at the 1 ms clock.
        const double ripple = 3 * std::sin(2 * kPi * double(t % 10) * 0.3);
        return rounded(readings().dcVoltageV + ripple + noise(4));
    }
    case LiveSignal::PeakDcVoltage:
        return rounded(m.peakDcVoltageV());
    case LiveSignal::HeatSink:
        return rounded(m.heatSinkC() + 40);
    case LiveSignal::InputState:
        return inputState(state);
    case LiveSignal::OutputState:
        return outputState(state);
    case LiveSignal::Overload: {
        const double load
            = std::abs(readings().torqueNm) / std::max(0.1, state.motorSettings().ratedTorqueNm);
        return std::clamp(rounded((load - 1.05) * 200), 0, 100);
    }
    case LiveSignal::LastError:
        return 0;
    case LiveSignal::ScopeTimer:
        return qint32(t & 0xFFFF);
    case LiveSignal::StatusHigh:
        return (inputState(state) & 0xFF) << 8 | outputState(state);
    case LiveSignal::StatusLow:
        return statusLow(state);
    case LiveSignal::StatusLong:
        return qint32(quint32((inputState(state) & 0xFF) << 8 | outputState(state)) << 16
                      | quint32(statusLow(state)));
    case LiveSignal::ControlLong:
        return qint32(quint32(state.setting(F5::kControlWordHigh, 0) & 0xFFFF) << 16
                      | quint32(state.setting(F5::kControlWordLow, 0) & 0xFFFF));
    case LiveSignal::Password:
        return -1 - state.passwordLevel();
    case LiveSignal::OperatingHours:
        return kOperatingHoursAtStart + qint32(state.uptimeMs() / 360000);
    case LiveSignal::ModulationHours:
        return kModulationHoursAtStart + qint32(m.modulationSeconds() / 360);
    case LiveSignal::SerialNumber:
        return state.serialNumber();
    case LiveSignal::EncoderPosition: {
        const double increments = m.revolutions() * 4 * state.setting(F5::kEncoderPulses, 1024);
        return qint32(qint64(std::floor(increments)) & 0xFFFF);
    }
    }
    return 0;
}

} // namespace DriveDesk::Sim
