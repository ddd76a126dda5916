#include "ValueChange.h"

#include "client/ValueRequests.h"
#include "parameters/SetList.h"

#include <QCoreApplication>

#include <memory>
#include <utility>

namespace DriveDesk {

namespace {

// The context of the texts of a change's read-back.
class ValueChangeText
{
    Q_DECLARE_TR_FUNCTIONS(ValueChangeText)
};

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
    bool activeSetFailed = false; // a step with set mask 0 was refused or got no answer

    // The value the last step that wrote `slot` asked for (a reset's is not known).
    std::optional<qint32> askedIn(std::size_t slot) const
    {
        std::optional<qint32> raw;
        for (const WriteStep &step : change.steps) {
            const bool writes = slot == kActiveSlot ? step.setMask == 0
                                                    : (step.setMask & (1u << slot)) != 0;
            if (writes)
                raw = step.reset ? std::nullopt : std::optional<qint32>(step.raw);
        }
        return raw;
    }
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

// The first request of the change that found the connection gone says why.
void failConnection(WriteOutcome &outcome, const QString &reason)
{
    if (!outcome.connectionFailed)
        outcome.connectionError = reason;
    outcome.connectionFailed = true;
}

constexpr int kReadBackAttempts = 3; // an implausible answer is read again so often in all

void finishReadBack(const ChangeRunPtr &run)
{
    if (run->readsOnTheWay != 0)
        return;
    WriteOutcome &outcome = run->outcome;
    // Every set that failed was settled by reading it: the write was taken after all.
    if (outcome.refusedMask == 0 && !run->activeSetFailed)
        outcome.error.clear();
    run->done(outcome);
}

// What a read of a set whose write got no answer settles: the value written means the write
// came through; another value means it did not; no value leaves it unknown.
void settleUnanswered(ChangeRun &run, std::size_t slot, qint32 held)
{
    WriteOutcome &outcome = run.outcome;
    const std::optional<qint32> asked = run.askedIn(slot);
    // A reset's value, or a parameter that may show another value than the one written (a
    // password): what it holds does not say whether the write came through.
    if (!asked || !run.change.readBackShowsWrite)
        return;
    if (slot == kActiveSlot) {
        outcome.activeSetUnanswered = false;
        if (held == asked) {
            outcome.activeSetAcknowledged = true;
            outcome.activeSetConfirmedByReading = true;
            run.activeSetFailed = false;
        }
        return;
    }
    const auto bit = quint8(1u << slot);
    outcome.unansweredMask &= quint8(~bit);
    if (held == asked) {
        outcome.refusedMask &= quint8(~bit);
        outcome.acknowledgedMask |= bit;
        outcome.confirmedByReadingMask |= bit;
    }
}

// Reads one set after the writes; `unanswered`: its write got no answer.
void readSlot(RequestSink &sink, const ChangeRunPtr &run, std::size_t slot, bool unanswered,
              int attemptsLeft)
{
    const std::size_t set = slot == kActiveSlot ? 0 : slot;
    sink.submit(readOf(run->protocol, run->change.address, slot),
                [&sink, run, slot, set, unanswered, attemptsLeft](const Reply &reply) {
                    WriteOutcome &outcome = run->outcome;
                    const auto *value = reply.data<ParameterValue>();
                    const QString implausible = value && run->change.implausible
                        ? run->change.implausible(value->value)
                        : QString();
                    if (value && !implausible.isEmpty() && attemptsLeft > 1)
                        return readSlot(sink, run, slot, unanswered, attemptsLeft - 1);
                    --run->readsOnTheWay;
                    if (value && implausible.isEmpty()) {
                        outcome.readBack.at(set) = value->value;
                        if (unanswered)
                            settleUnanswered(*run, slot, value->value);
                    } else if (outcome.readBackError.isEmpty()) {
                        outcome.readBackError = value
                            ? ValueChangeText::tr("the drive's answer cannot be its value: %1")
                                  .arg(implausible)
                            : reply.message();
                    }
                    if (reply.isConnectionFailure())
                        failConnection(outcome, reply.message());
                    finishReadBack(run);
                });
}

void readBack(RequestSink &sink, const ChangeRunPtr &run)
{
    WriteOutcome &outcome = run->outcome;
    QList<std::pair<std::size_t, bool>> wanted; // slot, and whether its write got no answer
    if (outcome.activeSetAcknowledged)
        wanted.append({kActiveSlot, false});
    else if (outcome.activeSetUnanswered)
        wanted.append({kActiveSlot, true});
    for (int set = 0; set < kParameterSets; ++set) {
        const auto bit = quint8(1u << set);
        if (outcome.acknowledgedMask & bit)
            wanted.append({std::size_t(set), false});
        else if (outcome.unansweredMask & bit)
            wanted.append({std::size_t(set), true});
    }
    QList<std::pair<std::size_t, bool>> reads;
    for (const auto &[slot, unanswered] : std::as_const(wanted)) {
        const EarlyRead &early = run->early.at(slot);
        const std::size_t set = slot == kActiveSlot ? 0 : slot;
        if (!unanswered && early.counts()) {
            outcome.readBack.at(set) = early.value;
        } else if (!unanswered && early.sent && early.connectionFailed) {
            // Nothing more gets through: asking again would only say so less precisely.
            if (outcome.readBackError.isEmpty())
                outcome.readBackError = early.error;
            failConnection(outcome, early.error);
        } else {
            reads.append({slot, unanswered});
        }
    }
    // Counted before the first is sent: a request that cannot be sent answers at once.
    run->readsOnTheWay = int(reads.size()) + 1;
    for (const auto &[slot, unanswered] : std::as_const(reads))
        readSlot(sink, run, slot, unanswered, kReadBackAttempts);
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
            if (step.setMask == 0)
                run->activeSetFailed = true;
            if (reply.attempts == 0) {
                outcome.notSentMask |= step.setMask;
            } else if (mayHaveTakenIt(reply)) {
                outcome.unansweredMask |= step.setMask;
                outcome.activeSetUnanswered = outcome.activeSetUnanswered || step.setMask == 0;
            }
            if (reply.isConnectionFailure()) {
                // The steps after it would fail alike: they stay unsent, neither acknowledged
                // nor refused, and what was acknowledged is still read back if it can be.
                failConnection(outcome, reply.message());
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
