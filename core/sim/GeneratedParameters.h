#pragma once

#include "ParameterDatabase.h"

namespace DriveDesk::Sim {

// The most parameters padding can reach: generated groups use pages 20h..7Fh (addresses stay
// below 8000h, where services 50/53 put their write flag), 200 parameters each.
constexpr int kGeneratedFirstPage = 0x20;
constexpr int kGeneratedLastPage = 0x7F;
constexpr int kGeneratedPerGroup = 200;

// Adds generated groups and parameters until `db` holds `total` parameters (at most the
// standard ones plus 96 * 200). Deterministic for a given seed: the same scan sees the same
// drive. Calls db.finish().
void addGeneratedParameters(ParameterDatabase &db, int total, quint32 seed);

} // namespace DriveDesk::Sim
