#include "ValueChange.h"

#include "client/ValueRequests.h"
#include "parameters/SetList.h"

#include <memory>
#include <utility>

namespace DriveDesk {

namespace {

constexpr std::size_t kActiveSlot = kParameterSets; // the early read of the active set

// A read-back sent right behind its write, before the write's answer (HSP5). It may show the
// drive before the write took effect: neither seed says that the drive finishes the up to four
// requests it holds in the order they came, and a write whose first attempt was lost is sent
// again after the read behind it. So it counts only where its write was answered OK and it
// shows the value written (the drive then held it, and a later attempt of the write puts the
// same); otherwise the set is read again once the write was answered.
struct EarlyRead
{
    bool sent = false;
    qsizetype step = -1; // the step whose write it follows
    qint32 written = 0;
    bool writeOk = false;
    std::optional<qint32> value;
    QString error;
    // No answer at all. It says something only where the write was acknowledged, as the
    // read-back's failure; a read behind a write that failed is no part of the outcome.
    bool connectionFailed = false;

    bool counts() const { return sent && writeOk && value == written; }
};

// The state of one change on its way; the requests' callbacks share it.
struct ChangeRun
{
    Protocol protocol = Protocol::Hsp5;
    ValueChange change;
    std::function<void(const WriteOutcome &)> done;
    std::function<void()> stepsDone;
    WriteOutcome outcome;
    qsizetype nextStep = 0;
    bool stepsAnswered = false;
    bool readingBack = false;
    int earlyOnTheWay = 0;
    int readsOnTheWay = 0;
    std::array<EarlyRead, kParameterSets + 1> early{}; // per set, then the active set
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

// The early-read slots a step writes: its sets, or the active set.
QList<std::size_t> slotsOf(const WriteStep &step)
{
    if (step.setMask == 0)
        return {kActiveSlot};
    QList<std::size_t> places;
    for (int set = 0; set < kParameterSets; ++set) {
        if (step.setMask & (1u << set))
            places << std::size_t(set);
    }
    return places;
}

Telegram readOf(Protocol protocol, quint16 address, std::size_t slot)
{
    return slot == kActiveSlot ? ValueRequests::readStandard(protocol, address)
                               : ValueRequests::read(address, quint8(1u << slot));
}

// Only the last step that may touch a set is read early: one the active set shares with every
// set, and a reset's value is not known before it is read.
bool readsEarly(const ChangeRun &run, qsizetype index)
{
    const WriteStep &step = run.change.steps.at(index);
    if (run.protocol != Protocol::Hsp5 || step.reset)
        return false;
    for (qsizetype later = index + 1; later < run.change.steps.size(); ++later) {
        const quint8 mask = run.change.steps.at(later).setMask;
        if (mask == 0 || step.setMask == 0 || (mask & step.setMask))
            return false;
    }
    return true;
}

void finishReadBack(const ChangeRunPtr &run)
{
    if (run->readsOnTheWay == 0)
        run->done(run->outcome);
}

void readBack(RequestSink &sink, const ChangeRunPtr &run)
{
    const quint16 address = run->change.address;
    QList<std::size_t> wanted;
    if (run->outcome.activeSetAcknowledged)
        wanted << kActiveSlot;
    for (int set = 0; set < kParameterSets; ++set) {
        if (run->outcome.acknowledgedMask & (1u << set))
            wanted << std::size_t(set);
    }
    QList<std::pair<std::size_t, Telegram>> reads;
    for (const std::size_t slot : std::as_const(wanted)) {
        const EarlyRead &early = run->early.at(slot);
        const std::size_t set = slot == kActiveSlot ? 0 : slot;
        if (early.counts()) {
            run->outcome.readBack.at(set) = early.value;
        } else if (early.sent && early.connectionFailed) {
            // Nothing more gets through: asking again would only say so less precisely.
            if (run->outcome.readBackError.isEmpty())
                run->outcome.readBackError = early.error;
            run->outcome.connectionFailed = true;
        } else {
            reads.append({set, readOf(run->protocol, address, slot)});
        }
    }
    // Counted before the first is sent: a request that cannot be sent answers at once.
    run->readsOnTheWay = int(reads.size()) + 1;
    for (const auto &[set, request] : reads) {
        sink.submit(request, [run, set = set](const Reply &reply) {
            --run->readsOnTheWay;
            if (const auto *value = reply.data<ParameterValue>())
                run->outcome.readBack.at(set) = value->value;
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

// The read-back starts once every step was answered and every early read is back.
void readBackWhenReady(RequestSink &sink, const ChangeRunPtr &run)
{
    if (!run->stepsAnswered || run->earlyOnTheWay > 0 || run->readingBack)
        return;
    run->readingBack = true;
    readBack(sink, run);
}

void readEarly(RequestSink &sink, const ChangeRunPtr &run, qsizetype index)
{
    const WriteStep &step = run->change.steps.at(index);
    const QList<std::size_t> places = slotsOf(step);
    for (const std::size_t slot : places) {
        EarlyRead &early = run->early.at(slot);
        early = {};
        early.sent = true;
        early.step = index;
        early.written = step.raw;
    }
    run->earlyOnTheWay += int(places.size());
    for (const std::size_t slot : places) {
        sink.submit(readOf(run->protocol, run->change.address, slot),
                    [&sink, run, slot](const Reply &reply) {
                        EarlyRead &early = run->early.at(slot);
                        if (const auto *value = reply.data<ParameterValue>())
                            early.value = value->value;
                        else
                            early.error = reply.message();
                        early.connectionFailed = reply.isConnectionFailure();
                        --run->earlyOnTheWay;
                        readBackWhenReady(sink, run);
                    });
    }
}

void sendNextStep(RequestSink &sink, const ChangeRunPtr &run)
{
    if (run->nextStep >= run->change.steps.size()) {
        if (const std::function<void()> stepsDone = std::exchange(run->stepsDone, {}))
            stepsDone();
        run->stepsAnswered = true;
        return readBackWhenReady(sink, run);
    }
    const qsizetype index = run->nextStep++;
    const WriteStep step = run->change.steps.at(index);
    const quint16 address = run->change.address;
    const Telegram request = step.reset ? ValueRequests::resetToDefault(address, step.setMask)
        : step.setMask == 0 ? ValueRequests::writeStandard(run->protocol, address, step.raw)
                            : ValueRequests::write(address, step.raw, step.setMask);
    auto answered = std::make_shared<bool>(false);
    sink.submit(request, [&sink, run, step, index, answered](const Reply &reply) {
        *answered = true;
        WriteOutcome &outcome = run->outcome;
        if (reply.ok()) {
            outcome.acknowledgedMask |= step.setMask;
            outcome.activeSetAcknowledged = outcome.activeSetAcknowledged || step.setMask == 0;
            for (const std::size_t slot : slotsOf(step)) {
                if (run->early.at(slot).step == index)
                    run->early.at(slot).writeOk = true;
            }
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
    // A write that was answered at once (it could not be sent) has nothing to read early.
    if (!*answered && readsEarly(*run, index))
        readEarly(sink, run, index);
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
