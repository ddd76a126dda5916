#pragma once

#include "LiveSignal.h"

#include <QtGlobal>

namespace DriveDesk::Sim {

class DriveState;

// The raw value of a live signal now (units as LiveSignal lists them). `index` is the
// parameter that shows it, for the signals that keep a value (peaks, control word).
qint32 liveValue(const DriveState &state, LiveSignal signal, int index);

// A deterministic pseudo-random number in [-1, 1] for `seed`, `channel` and time.
double measurementNoise(quint32 seed, quint32 channel, qint64 timeMs);

} // namespace DriveDesk::Sim
