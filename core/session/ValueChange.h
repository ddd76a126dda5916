#pragma once

#include "client/RequestJob.h"
#include "protocol/Codec.h"
#include "parameters/DriveDescription.h"

#include <QList>
#include <QString>

#include <array>
#include <functional>
#include <optional>

namespace DriveDesk {

// One step of a change to a parameter: one value written to the sets of a mask (service 0), or
// those sets reset to their default (service 32). Set mask 0 writes the active set (service 1,
// set 0); a reset always names its sets.
struct WriteStep
{
    quint8 setMask = 0;
    qint32 raw = 0; // not used by a reset
    bool reset = false;
};

// A change of one parameter's values: its steps, written in order.
struct ValueChange
{
    quint16 address = 0;
    // The steps' masks go through SetList::setsWritten() before they are sent.
    bool setProgrammable = true;
    QList<WriteStep> steps;
    // Why a value read back cannot be the parameter's (outside its limits: implausibleValue()),
    // empty when it can be. Such an answer is read again and never believed. Unset: any value.
    std::function<QString(qint32)> implausible;
    // The drive holds what was written once it took it (not so for readBackMayDiffer()).
    bool readBackShowsWrite = true;
};

// What became of a change. A change counts once the drive shows the value: every set it
// acknowledged is read back.
struct WriteOutcome
{
    quint16 address = 0;
    quint8 acknowledgedMask = 0; // sets whose write the drive acknowledged
    quint8 refusedMask = 0;      // sets whose write was refused or never answered
    // Of refusedMask: sets whose write went on the line and got no answer the drive gave (no
    // answer at all, or only a garbled one after an attempt that may have reached it): the
    // drive may hold the value or not.
    quint8 unansweredMask = 0;
    // Sets whose write got no answer, but a read afterwards showed the value written: they count
    // as acknowledged (and are in acknowledgedMask, not in refusedMask or unansweredMask).
    quint8 confirmedByReadingMask = 0;
    // Sets whose write never went on the line: queued when the connection failed, or a step
    // after the one that failed. The drive holds what it held.
    quint8 notSentMask = 0;
    bool activeSetAcknowledged = false; // a step with set mask 0
    // A step with set mask 0 whose write got no answer and whose read did not settle it.
    bool activeSetUnanswered = false;
    bool activeSetConfirmedByReading = false;
    QString error;               // the first refusal or transport failure, in words
    // No answer at all, to a write or a read-back: later requests would fail alike. The steps
    // after the failed one were not sent: their sets are neither acknowledged nor refused.
    bool connectionFailed = false;
    QString connectionError; // why, in words, when connectionFailed
    QString readBackError;       // acknowledged, but the value could not be read back
    // What the drive holds after the change, per set read back ([0] for the active set).
    std::array<std::optional<qint32>, kParameterSets> readBack{};

    bool ok() const { return refusedMask == 0 && error.isEmpty(); }
    // Sets the drive may hold the value in or not: their write was never answered, and reading
    // them afterwards did not settle it either.
    quint8 unknownMask() const { return unansweredMask; }
    bool anyUnknown() const { return unansweredMask != 0 || activeSetUnanswered; }
    bool anyAcknowledged() const { return acknowledgedMask != 0 || activeSetAcknowledged; }
};

// Sends the change's steps one after the other on `sink`, then reads back every set the drive
// acknowledged, and every set whose write got no answer (no answer is not a refusal: a set
// that then shows the value written was written, one that shows another value was not, and one
// that cannot be read stays unknown); `stepsDone` (if given) runs once when the last step is answered, before the
// read-back, and `done` runs once with the outcome. Over HSP5 a step's sets are read right
// behind its write, without waiting for its answer, so that the line carries both at once; such
// a read counts only once the write was answered OK and only when it shows the value written,
// else the set is read again. Thread: the sink's.
void sendValueChange(RequestSink &sink, Protocol protocol, ValueChange change,
                     std::function<void(const WriteOutcome &)> done,
                     std::function<void()> stepsDone = {});

// One change as a job of its own; ValueEdits runs the window's and the command line's edits so.
class WriteValueJob : public RequestJob<WriteOutcome>
{
public:
    WriteValueJob(Protocol protocol, ValueChange change);

private:
    void start() override;

    const Protocol m_protocol;
    const ValueChange m_change;
};

} // namespace DriveDesk
