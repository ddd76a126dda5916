#include "ValueChange.h"

#include "client/ValueRequests.h"
#include "parameters/SetList.h"

#include <memory>

namespace DriveDesk {

namespace {

// The state of one change on its way; the requests' callbacks share it.
struct ChangeRun
{
    Protocol protocol = Protocol::Hsp5;
    ValueChange change;
    std::function<void(const WriteOutcome &)> done;
    WriteOutcome outcome;
    qsizetype nextStep = 0;
    int readsOnTheWay = 0;
};
using ChangeRunPtr = std::shared_ptr<ChangeRun>;

void sendNextStep(RequestSink &sink, const ChangeRunPtr &run);

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
    if (run->nextStep >= run->change.steps.size())
        return readBack(sink, run);
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
            if (reply.isConnectionFailure()) {
                // The steps after it would fail alike: they stay unsent, neither acknowledged
                // nor refused, and what was acknowledged is still read back if it can be.
                outcome.connectionFailed = true;
                run->nextStep = run->change.steps.size();
            }
        }
        sendNextStep(sink, run);
    });
}

} // namespace

void sendValueChange(RequestSink &sink, Protocol protocol, ValueChange change,
                     std::function<void(const WriteOutcome &)> done)
{
    auto run = std::make_shared<ChangeRun>();
    run->protocol = protocol;
    run->outcome.address = change.address;
    for (WriteStep &step : change.steps)
        step.setMask = SetList::setsWritten(change.setProgrammable, step.setMask);
    run->change = std::move(change);
    run->done = std::move(done);
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
