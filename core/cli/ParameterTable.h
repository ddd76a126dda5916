#pragma once

#include "parameters/DriveDescription.h"
#include "protocol/Language.h"

#include <QString>

namespace DriveDesk {

// Plain-text reports of a drive for a terminal: aligned columns, values as the drive shows them.
namespace ParameterTable {

// The value as the drive would show it: its plaintext, or scaled with unit and decimals.
QString valueText(const ParameterDescription &parameter, qint32 raw, bool withUnit = true);
QString scan(const DriveDescription &drive, bool withValues, Language language);
// Identification, groups and parameter counts; `system` holds the Sy group with values.
QString info(const DriveDescription &drive, const DriveDescription &system, Language language);

} // namespace ParameterTable

} // namespace DriveDesk
