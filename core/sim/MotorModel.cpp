#include "MotorModel.h"

#include <algorithm>
#include <cmath>

namespace DriveDesk::Sim {

namespace {

constexpr double kInertia = 0.2; // kg m^2, motor and load
constexpr double kAmbientC = 30;
constexpr double kHeatPerAmpere = 3.0; // K of heat-sink rise per A, steady state
constexpr double kHeatTimeConstantS = 90;
constexpr double kDcLinkV = 540; // 400 V mains, rectified
constexpr double kTwoPi = 6.283185307179586;

// Ru.00 codes (keb_f5_params.csv).
enum StateCode : int {
    NoOperation = 0,
    Facc = 64,
    Fdec = 65,
    Fcon = 66,
    RAcc = 67,
    RDec = 68,
    RCon = 69
};

} // namespace

void MotorModel::run(double seconds, double targetRpm, const MotorSettings &settings)
{
    if (seconds <= 0)
        return;
    m_targetRpm = targetRpm;
    double remaining = seconds;
    m_accelerationRpmPerS = 0;
    while (remaining > 0 && m_speedRpm != targetRpm) {
        // Towards zero is deceleration; crossing zero stops there first.
        const bool awayFromZero = (m_speedRpm >= 0 && targetRpm > m_speedRpm)
            || (m_speedRpm <= 0 && targetRpm < m_speedRpm);
        double next = targetRpm;
        if (!awayFromZero
            && ((m_speedRpm > 0 && targetRpm < 0) || (m_speedRpm < 0 && targetRpm > 0)))
            next = 0;
        const double rate
            = awayFromZero ? settings.accelerationRpmPerS : settings.decelerationRpmPerS;
        const double direction = next > m_speedRpm ? 1.0 : -1.0;
        const double needed = rate > 0 ? std::abs(next - m_speedRpm) / rate : 0;
        const double step = std::min(remaining, needed);
        const double end = step < needed ? m_speedRpm + direction * rate * step : next;
        m_revolutions += (m_speedRpm + end) / 2 * step / 60;
        m_speedRpm = end;
        m_accelerationRpmPerS = rate > 0 ? direction * rate : 0;
        remaining -= step;
        if (step == needed && m_speedRpm == targetRpm && remaining > 0)
            m_accelerationRpmPerS = 0;
    }
    if (remaining > 0)
        m_revolutions += m_speedRpm * remaining / 60;
    m_revolutions = std::fmod(m_revolutions, 1e6);

    const MotorReadings now = readings(settings);
    if (now.modulating)
        m_modulationSeconds += seconds;
    const double steady = kAmbientC + kHeatPerAmpere * now.currentA;
    m_heatSinkC = steady + (m_heatSinkC - steady) * std::exp(-seconds / kHeatTimeConstantS);
    m_peakCurrentA = std::max(m_peakCurrentA, now.currentA);
    m_peakDcVoltageV = std::max(m_peakDcVoltageV, now.dcVoltageV);
}

int MotorModel::stateCode() const
{
    if (m_speedRpm == 0 && m_targetRpm == 0)
        return NoOperation;
    const bool forward = m_speedRpm > 0 || (m_speedRpm == 0 && m_targetRpm > 0);
    if (m_accelerationRpmPerS > 0)
        return forward ? Facc : RDec;
    if (m_accelerationRpmPerS < 0)
        return forward ? Fdec : RAcc;
    if (m_speedRpm == m_targetRpm)
        return forward ? Fcon : RCon;
    // A step to the set value without a ramp: constant at once.
    return forward ? Fcon : RCon;
}

MotorReadings MotorModel::readings(const MotorSettings &s) const
{
    MotorReadings r;
    r.modulating = m_speedRpm != 0 || m_targetRpm != 0;
    const double pairs = std::max(1, s.polePairs);
    r.outputFrequencyHz = m_speedRpm * pairs / 60;
    r.setFrequencyHz = m_targetRpm * pairs / 60;
    if (!r.modulating) {
        r.dcVoltageV = kDcLinkV;
        return r;
    }
    const double ratedSynchronous = 60 * s.ratedFrequencyHz / pairs;
    const double nominal = std::max(1.0, s.ratedSpeedRpm);
    const double ratio = m_speedRpm / nominal;
    const double direction = m_speedRpm > 0 ? 1.0 : (m_speedRpm < 0 ? -1.0 : 0.0);
    const double load = s.ratedTorqueNm * (0.4 * ratio * std::abs(ratio)) + 0.5 * direction;
    const double acceleration = kInertia * m_accelerationRpmPerS * kTwoPi / 60;
    r.torqueNm = load + acceleration;
    const double slip = (ratedSynchronous - nominal) * r.torqueNm / std::max(0.1, s.ratedTorqueNm);
    r.shaftSpeedRpm = m_speedRpm - slip;
    const double torqueCurrentRated = std::sqrt(std::max(
        0.0, s.ratedCurrentA * s.ratedCurrentA - s.magnetisingCurrentA * s.magnetisingCurrentA));
    const double torqueCurrent = torqueCurrentRated * r.torqueNm / std::max(0.1, s.ratedTorqueNm);
    r.currentA
        = std::sqrt(s.magnetisingCurrentA * s.magnetisingCurrentA + torqueCurrent * torqueCurrent);
    const double boost = s.cornerVoltageV * s.boostPercent / 100;
    const double corner = std::max(1.0, s.cornerFrequencyHz);
    r.outputVoltageV
        = std::min(s.cornerVoltageV,
                   boost + (s.cornerVoltageV - boost) * std::abs(r.outputFrequencyHz) / corner);
    r.powerKw = r.torqueNm * r.shaftSpeedRpm * kTwoPi / 60 / 1000;
    // Braking feeds the DC link; motoring draws it down a little.
    r.dcVoltageV
        = r.powerKw < 0 ? kDcLinkV + std::min(160.0, -r.powerKw * 60) : kDcLinkV - r.powerKw * 3;
    return r;
}

} // namespace DriveDesk::Sim
