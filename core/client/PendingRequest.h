#pragma once

#include "client/Reply.h"

#include <QDeadlineTimer>

#include <array>
#include <functional>
#include <optional>

namespace DriveDesk {

// What a job in the worker thread asks of one request beyond its telegram.
struct RequestOptions {
    int timeoutMs = 0;  // 0: the client's answer timeout
    int retries = -1;   // -1: ClientOptions::retries
    quint64 owner = 0;  // ClientWorker::cancelOwner() drops the requests of one job
    bool probe = false; // may go unanswered (no drive at the address): says nothing of silence
};

// How a request ended. `heard`: something came back while it waited, even a garbled answer,
// so a drive is there.
using Completion = std::function<void(const Reply &reply, bool heard)>;

// What an attempt got instead of a valid answer (ClientSilence.cpp): the first garbage that
// came after it went out, or nothing at all. A run of requests given up is named after the
// most frequent, and where two are as frequent, after the one listed first.
enum class Garbage : quint8 {
    StaleAnswer,   // matches a request sent earlier, not an open one
    WrongLength,   // a frame cut short, too long, or its fields not filling it
    Checksum,      // a frame whose BCC is wrong
    ForeignAnswer, // a telegram that matches no request sent
    LineError,     // characters the UART flagged (parity, framing, overrun)
    Unframed,      // bytes that never made a telegram
    Nothing,       // silence
};
constexpr int kGarbageKinds = int(Garbage::Nothing) + 1;

// One request in the client's queue, from submission until its answer or its end.
// A request whose completion already ran (cancelled while its answer is on the way) stays in
// flight until that answer or its timeout: the drive still works on it, and its answer must
// not be taken for another request's.
struct PendingRequest {
    enum class Stage : quint8 {
        Queued,
        AwaitingAnswer,
        Backoff, // the drive said busy: waiting before the next attempt
    };

    quint64 ticket = 0;
    RequestOptions options;
    Telegram request;   // as submitted
    Telegram wire;      // the latest attempt on the wire: invoke id, selection
    int target = -1;    // DIN66019(II): the drive address it goes to
    int timeoutMs = 0;
    int maxAttempts = 1;
    Completion done;    // empty once it ran
    Stage stage = Stage::Queued;
    QDeadlineTimer deadline;
    quint64 answersBefore = 0; // answers the client had matched when this attempt went out
    quint64 receptionsBefore = 0; // bytes the client had received when it first went out
    quint64 receptionsAtAttempt = 0; // ... and when its latest attempt went out
    quint8 receivedXorAtAttempt = 0; // ... and the XOR of every byte received till then
    // What its attempts got instead of an answer: the latest one so far, the first, and the
    // later ones by kind. Attempts during which another request was answered are left out and
    // counted.
    std::optional<Garbage> attemptGarbage;
    std::optional<Garbage> firstAttemptGot;
    std::array<int, kGarbageKinds> laterAttemptsGot{};
    int overtakenAttempts = 0;

    int attempts = 0;
    int timeouts = 0;
    int checksumErrors = 0;
    int otherDecodeErrors = 0;
    int lineErrors = 0; // parity, framing or overrun errors the link reported
    int mismatches = 0;
    int transientAcks = 0;
    Ack lastTransientAck = Ack::Ok;
    bool heard = false;

    bool completed() const { return !done; }
};

} // namespace DriveDesk
