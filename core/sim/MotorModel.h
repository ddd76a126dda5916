#pragma once

#include <QtGlobal>

namespace DriveDesk::Sim {

// The motor data and ramps the model runs with, in SI units (from dr, uF and the active set's
// op parameters).
struct MotorSettings
{
    double accelerationRpmPerS = 0; // 0: no ramp, the set value is reached at once
    double decelerationRpmPerS = 0;
    int polePairs = 2;
    double ratedSpeedRpm = 1450;
    double ratedFrequencyHz = 50;
    double ratedCurrentA = 8.5;
    double magnetisingCurrentA = 3.2;
    double ratedTorqueNm = 26.3;
    double cornerFrequencyHz = 50;
    double cornerVoltageV = 400;
    double boostPercent = 2;
};

// What the drive measures, derived from the motor's state.
struct MotorReadings
{
    bool modulating = false;
    double outputFrequencyHz = 0;
    double setFrequencyHz = 0;
    double shaftSpeedRpm = 0;
    double torqueNm = 0;
    double currentA = 0;
    double outputVoltageV = 0;
    double powerKw = 0;
    double dcVoltageV = 0; // without ripple
};

// An induction motor on a V/f inverter with linear ramps, a fan-like load and a heat sink
// that warms with the current. Pure arithmetic: the caller supplies elapsed time and set value.
class MotorModel
{
public:
    // Runs for `seconds` towards `targetRpm` (synchronous speed; the sign is the direction).
    void run(double seconds, double targetRpm, const MotorSettings &settings);

    double speedRpm() const { return m_speedRpm; } // ramp output, synchronous speed
    double targetRpm() const { return m_targetRpm; }
    double accelerationRpmPerS() const { return m_accelerationRpmPerS; } // d speed / dt now
    double heatSinkC() const { return m_heatSinkC; }
    double revolutions() const { return m_revolutions; }
    double modulationSeconds() const { return m_modulationSeconds; }
    double peakCurrentA() const { return m_peakCurrentA; }
    double peakDcVoltageV() const { return m_peakDcVoltageV; }
    void setPeakCurrentA(double value) { m_peakCurrentA = value; }
    void setPeakDcVoltageV(double value) { m_peakDcVoltageV = value; }

    // The ru.00 state code: noP, Facc/Fdec/Fcon, rAcc/rdEc/rCon.
    int stateCode() const;
    MotorReadings readings(const MotorSettings &settings) const;

private:
    double m_speedRpm = 0;
    double m_targetRpm = 0;
    double m_accelerationRpmPerS = 0;
    double m_heatSinkC = 30;
    double m_revolutions = 0;
    double m_modulationSeconds = 0;
    double m_peakCurrentA = 0;
    double m_peakDcVoltageV = 0;
};

} // namespace DriveDesk::Sim
