#pragma once

#include "DriveDescription.h"
#include "JsonObjectReader.h"
#include "ParameterId.h"

#include <QList>

namespace DriveDesk::ParameterDocumentChecks {

// The fields written for readers (id, unit, decimals, setProgrammable, readOnly) must agree
// with the data they are derived from: an edit to them alone would otherwise be lost.
void checkDerived(JsonObjectReader &reader, const ParameterDescription &parameter,
                  const QList<GroupAddress> &groups);
// What no drive can report: min above max, a constant default outside constant limits.
void checkLimits(JsonObjectReader &reader, const ParameterDescription &parameter);

} // namespace DriveDesk::ParameterDocumentChecks
