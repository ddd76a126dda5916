#pragma once

#include "plant/PlantDock.h"

#include <QAction>
#include <QTest>

// The plant view's jobs in the tests of the window.
namespace DriveDesk::PlantTest {

// A job works through every drive, a search through 240 addresses.
constexpr int kJobWaitMs = 60000;

// Triggers a job's action, if it is enabled, and waits until the job has ended.
inline bool runJob(const PlantDock &dock, QAction *action)
{
    if (!action->isEnabled())
        return false;
    action->trigger();
    return QTest::qWaitFor([&dock] { return dock.job() == PlantDock::Job::None; }, kJobWaitMs);
}

} // namespace DriveDesk::PlantTest
