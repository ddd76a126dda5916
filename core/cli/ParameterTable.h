#pragma once

#include "parameters/DriveDescription.h"
#include "parameters/ParameterComparison.h"

#include <QString>

namespace DriveDesk {

// Plain-text reports of a drive for a terminal: aligned columns, values as the drive shows them,
// headings in the installed language.
namespace ParameterTable {

// The value as the drive would show it: its plaintext, or scaled with unit and decimals.
QString valueText(const ParameterDescription &parameter, qint32 raw, bool withUnit = true);
QString scan(const DriveDescription &drive, bool withValues);
// Identification, groups and parameter counts; `system` holds the Sy group with values.
QString info(const DriveDescription &drive, const DriveDescription &system);
// Each difference of two parameter files on a line: id, name, set, both values, then a count.
QString differences(const ParameterComparison &comparison, const QString &a, const QString &b);

} // namespace ParameterTable

} // namespace DriveDesk
