#pragma once

#include "PlantRun.h"

namespace DriveDesk {

// A plant's verify of one drive: `drive`, read whole as a backup reads it, against `file`, its
// parameter file. Settings only (compareDescriptions); a file made for another kind of drive is
// judged by the rule that refuses a download (kindProblems), not compared value by value.
// Sets `result`'s outcome (Equal, Different with the differences, OtherKind with why).
void judgeVerify(const DriveDescription &file, const DriveDescription &drive,
                 PlantDrive &result);

} // namespace DriveDesk
