#include "PlantVerify.h"

#include "session/DownloadPlan.h"

namespace DriveDesk {

void judgeVerify(const DriveDescription &file, const DriveDescription &drive, PlantDrive &result)
{
    const QStringList problems = kindProblems(file, drive);
    if (!problems.isEmpty()) {
        result.outcome = PlantDrive::Outcome::OtherKind;
        result.reason = problems.join(QStringLiteral("; "));
        return;
    }
    result.differences = compareDescriptions(file, drive).differences;
    result.outcome = result.differences.isEmpty() ? PlantDrive::Outcome::Equal
                                                  : PlantDrive::Outcome::Different;
}

} // namespace DriveDesk
