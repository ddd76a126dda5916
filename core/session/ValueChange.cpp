#include "ValueChange.h"

#include "client/ValueRequests.h"
#include "parameters/SetList.h"

#include <memory>
#include <utility>

namespace DriveDesk {

namespace {

// The state of one change on its way; the requests' callbacks share it.
struct ChangeRun
{
    Protocol protocol = Protocol::Hsp5;
    ValueChange change;
    std::function<void(const WriteOutcome &)> done;
    std::function<void()> stepsDone;
    WriteOutcome outcome;
    qsizetype nextStep = 0;
    int readsOnTheWay = 0;
};
using ChangeRunPtr = std::shared_ptr<ChangeRun>;

void sendNextStep(RequestSink &sink, const ChangeRunPtr &run);

// A write that went on the line and got no word of the drive's on it: its answer was lost, or
// the drive only said it could not read a repetition, while an earlier attempt may have come
// through.
bool mayHaveTakenIt(const Reply &reply)
{
    if (reply.attempts == 0 || reply.isAnswer())
        return false;
    return reply.status != Reply::Status::Refused || reply.attempts > 1;
}

void finishReadBack(const ChangeRunPtr &run)
{
    if (run->readsOnTheWay == 0)
        run->done(run->outcome);
}

void readBack(RequestSink &sink, const ChangeRunPtr &run)
{
    const quint16 address = run->change.address;
    QList<std::pair<int, Telegram>> reads;
    if (run->outcome.activeSetAcknowledged)
        reads.append({0, ValueRequests::readStandard(run->protocol, address)});
    for (int set = 0; set < kParameterSets; ++set) {
        if (run->outcome.acknowledgedMask & (1u << set))
            reads.append({set, ValueRequests::read(address, quint8(1u << set))});
    }
    // Counted before the first is sent: a request that cannot be sent answers at once.
    run->readsOnTheWay = int(reads.size()) + 1;
    for (const auto &[set, request] : reads) {
        sink.submit(request, [run, set = set](const Reply &reply) {
            --run->readsOnTheWay;
            if (const auto *value = reply.data<ParameterValue>())
                run->outcome.readBack[std::size_t(set)] = value->value;
            else if (run->outcome.readBackError.isEmpty())
                run->outcome.readBackError = reply.message();
            if (reply.isConnectionFailure())
                run->outcome.connectionFailed = true;
            finishReadBack(run);
        });
    }
    --run->readsOnTheWay;
    finishReadBack(run);
}

void sendNextStep(RequestSink &sink, const ChangeRunPtr &run)
{
    if (run->nextStep >= run->change.steps.size()) {
        if (const std::function<void()> stepsDone = std::exchange(run->stepsDone, {}))
            stepsDone();
        return readBack(sink, run);
    }
    const WriteStep step = run->change.steps.at(run->nextStep++);
    const quint16 address = run->change.address;
    const Telegram request = step.reset ? ValueRequests::resetToDefault(address, step.setMask)
        : step.setMask == 0 ? ValueRequests::writeStandard(run->protocol, address, step.raw)
                            : ValueRequests::write(address, step.raw, step.setMask);
    sink.submit(request, [&sink, run, step](const Reply &reply) {
        WriteOutcome &outcome = run->outcome;
        if (reply.ok()) {
            outcome.acknowledgedMask |= step.setMask;
            outcome.activeSetAcknowledged = outcome.activeSetAcknowledged || step.setMask == 0;
        } else {
            outcome.refusedMask |= step.setMask;
            if (outcome.error.isEmpty())
                outcome.error = reply.message();
            if (reply.attempts == 0)
                outcome.notSentMask |= step.setMask;
            else if (mayHaveTakenIt(reply))
                outcome.unansweredMask |= step.setMask;
            if (reply.isConnectionFailure()) {
                // The steps after it would fail alike: they stay unsent, neither acknowledged
                // nor refused, and what was acknowledged is still read back if it can be.
                outcome.connectionFailed = true;
                for (qsizetype next = run->nextStep; next < run->change.steps.size(); ++next)
                    outcome.notSentMask |= run->change.steps.at(next).setMask;
                run->nextStep = run->change.steps.size();
            }
        }
        sendNextStep(sink, run);
    });
}

} // namespace

void sendValueChange(RequestSink &sink, Protocol protocol, ValueChange change,
                     std::function<void(const WriteOutcome &)> done,
                     std::function<void()> stepsDone)
{
    auto run = std::make_shared<ChangeRun>();
    run->protocol = protocol;
    run->outcome.address = change.address;
    for (WriteStep &step : change.steps)
        step.setMask = SetList::setsWritten(change.setProgrammable, step.setMask);
    run->change = std::move(change);
    run->done = std::move(done);
    run->stepsDone = std::move(stepsDone);
    sendNextStep(sink, run);
}

WriteValueJob::WriteValueJob(Protocol protocol, ValueChange change)
    : m_protocol(protocol)
    , m_change(std::move(change))
{}

void WriteValueJob::start()
{
    // A change once begun runs to its read-back: a cancel must not leave a write unconfirmed.
    sendValueChange(sink(), m_protocol, m_change, [this](const WriteOutcome &outcome) {
        promise().addResult(outcome);
        end();
    });
}

} // namespace DriveDesk
