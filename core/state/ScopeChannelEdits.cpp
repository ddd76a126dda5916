#include "ScopeChannelEdits.h"

#include "client/DriveClient.h"
#include "client/WhenFinished.h"
#include "state/ValueEdits.h"

namespace DriveDesk {

namespace {

void readAssignment(ValueEdits &edits, const DriveDescription &drive, ScopeChannelsOutcome written,
                    std::function<void(const ScopeChannelsOutcome &)> done)
{
    const auto job = std::make_shared<ScopeChannelsJob>(edits.client()->settings().protocol, drive);
    whenFinished(
        edits.client()->run(job), &edits,
        [written, done](const ScopeChannelsOutcome &read) {
            ScopeChannelsOutcome outcome = read;
            // The write's failure is the one to tell; what was read shows what came of it.
            if (!written.error.isEmpty()) {
                outcome.error = written.error;
                outcome.connectionFailed = written.connectionFailed;
            }
            done(outcome);
        },
        [done] {
            ScopeChannelsOutcome dropped;
            dropped.error = ValueEdits::tr("the connection to the drive was closed");
            dropped.connectionFailed = true;
            done(dropped);
        });
}

} // namespace

void assignScopeChannels(ValueEdits &edits, const DriveDescription &drive,
                         const ScopeAssignment &choices,
                         std::function<void(const ScopeChannelsOutcome &)> done)
{
    const ScopeChannelWrites planned = planScopeChannels(drive, choices);
    if (!planned.error.isEmpty()) {
        ScopeChannelsOutcome refused;
        refused.error = planned.error;
        refused.refusedChoice = true;
        return done(refused);
    }
    QList<ValueEdits::BatchItem> items;
    for (const ScopeChannelWrites::Write &write : planned.writes) {
        // scopeAssignmentParameters() found every one of them in `drive`.
        const ParameterDescription *parameter = drive.find(write.address);
        Q_ASSERT(parameter);
        // The set the drive records from: the active one where the assignment is per set, else
        // its one value, as the table writes it.
        const quint8 sets = parameter->isSetProgrammable() ? 0 : 0x01;
        items << ValueEdits::BatchItem { *parameter, { WriteStep { sets, write.raw, false } } };
    }
    edits.applyAll(items, {},
                   [&edits, drive, done = std::move(done)](const QList<EditOutcome> &outcomes) {
                       ScopeChannelsOutcome written;
                       for (const EditOutcome &outcome : outcomes) {
                           if (outcome.ok())
                               continue;
                           written.error = outcome.error;
                           written.connectionFailed = outcome.connectionFailed;
                           break;
                       }
                       // What did reach the drive is still read back, where the link allows.
                       if (written.connectionFailed)
                           return done(written);
                       readAssignment(edits, drive, written, done);
                   });
}

} // namespace DriveDesk
