#include "LiveSignal.h"

#include <QLatin1StringView>

namespace DriveDesk::Sim {

namespace {

struct SignalName
{
    const char *name;
    LiveSignal signal;
};

constexpr SignalName kNames[] = {
    { "state", LiveSignal::State },
    { "setFrequency", LiveSignal::SetFrequency },
    { "actualFrequency", LiveSignal::ActualFrequency },
    { "setSpeed", LiveSignal::SetSpeed },
    { "actualSpeed", LiveSignal::ActualSpeed },
    { "outputVoltage", LiveSignal::OutputVoltage },
    { "outputPower", LiveSignal::OutputPower },
    { "torqueSet", LiveSignal::TorqueSet },
    { "actualTorque", LiveSignal::ActualTorque },
    { "load", LiveSignal::Load },
    { "apparentCurrent", LiveSignal::ApparentCurrent },
    { "peakCurrent", LiveSignal::PeakCurrent },
    { "dcVoltage", LiveSignal::DcVoltage },
    { "peakDcVoltage", LiveSignal::PeakDcVoltage },
    { "heatSink", LiveSignal::HeatSink },
    { "inputState", LiveSignal::InputState },
    { "outputState", LiveSignal::OutputState },
    { "overload", LiveSignal::Overload },
    { "lastError", LiveSignal::LastError },
    { "scopeTimer", LiveSignal::ScopeTimer },
    { "statusHigh", LiveSignal::StatusHigh },
    { "statusLow", LiveSignal::StatusLow },
    { "statusLong", LiveSignal::StatusLong },
    { "controlLong", LiveSignal::ControlLong },
    { "password", LiveSignal::Password },
    { "operatingHours", LiveSignal::OperatingHours },
    { "modulationHours", LiveSignal::ModulationHours },
    { "serialNumber", LiveSignal::SerialNumber },
    { "encoderPosition", LiveSignal::EncoderPosition },
};

} // namespace

std::optional<LiveSignal> liveSignalFromName(const QString &name)
{
    if (name.isEmpty())
        return LiveSignal::None;
    for (const SignalName &entry : kNames) {
        if (name == QLatin1StringView(entry.name))
            return entry.signal;
    }
    return std::nullopt;
}

} // namespace DriveDesk::Sim
