#pragma once

#include "client/Reply.h"

#include <QDeadlineTimer>

#include <functional>

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
