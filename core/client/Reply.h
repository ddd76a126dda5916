#pragma once

#include "protocol/Telegram.h"

#include <QMetaType>
#include <QString>

namespace DriveDesk {

// The outcome of one request sent through the client.
struct Reply {
    enum class Status : quint8 {
        Ok,           // answered with ack 0
        Refused,      // answered with an error acknowledge: see response.ack
        Timeout,      // no valid answer after every retry
        LinkLost,     // the link went away while the request was queued or in flight
        Cancelled,
        NotConnected,
        Unsupported,  // the protocol cannot express this request (encode failed)
        NoReply,      // DIN66019II broadcast and group writes are never answered: sent, not confirmed
        DriveSilent,  // the drive stopped answering altogether (detail: how many requests in
                      // how long); given up at once, see docs/client.md
    };

    Status status = Status::NotConnected;
    Telegram request;
    Telegram response; // valid for Ok and Refused
    int attempts = 0;
    QString detail;    // what went wrong in transport terms, e.g. "3 BCC errors"
    // A read asked again to confirm it (a line with errors, docs/client.md) whose answers never
    // agreed: the drive answered, but which answer was its word is unknown.
    bool disagreed = false;

    bool ok() const { return status == Status::Ok; }
    // The drive's own word on the request: its data, or a refusal that is not about the
    // transmission (busy, a garbled request). Only such an answer says whether something exists.
    bool isAnswer() const;
    Ack ack() const { return response.ack; }
    // The answer's data, or null. Only on a Reply that outlives the pointer: a temporary's
    // pointer would dangle as soon as the statement ends.
    template<typename T> const T *data() const & { return ok() ? response.as<T>() : nullptr; }
    template<typename T> const T *data() const && = delete;
    // The transport gave up (link lost, not connected, cancelled, a drive that stopped
    // answering): no answer from the drive at all, so every later request of the same job
    // fails alike.
    bool isConnectionFailure() const
    {
        return status == Status::LinkLost || status == Status::NotConnected
            || status == Status::Cancelled || status == Status::DriveSilent;
    }
    // A sentence for a user in the installed language: "drive refused: data invalid", "no valid
    // answer from the drive after 4 attempts (4 timeouts; timeout 60 ms)".
    QString message() const;
};

QString statusName(Reply::Status status);

} // namespace DriveDesk

Q_DECLARE_METATYPE(DriveDesk::Reply)
