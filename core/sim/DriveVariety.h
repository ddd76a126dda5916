#pragma once

#include "ParameterDatabase.h"
#include "SimulatedDrive.h"

#include <memory>

namespace DriveDesk::Sim {

class DriveState;

// What sets one simulated drive apart from the others on its bus: the metadata of its kind,
// and a few user settings its address gives it, so that two drives' parameter files differ
// and a change to one shows on that one only.

// The parameters of a drive of `kind`; the standard F5 padded to `parameterCount` with
// parameters generated from `seed` (equal seeds, equal metadata).
std::shared_ptr<const ParameterDatabase> databaseFor(SimulatedDriveKind kind, int parameterCount,
                                                     quint32 seed);

// Acceleration time (op.28), quick stop time (op.35) and fixed speed 1 (op.20) in every set,
// from the drive's address: drive 1 keeps the data's values, each address above or below
// moves them by a step. Live values stay live; set value source and demo cycle are untouched.
void giveOwnSettings(DriveState &state);

} // namespace DriveDesk::Sim
