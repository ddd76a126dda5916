#pragma once

#include "client/RequestJob.h"
#include "protocol/Codec.h"
#include "session/ScopeAssignment.h"

#include <QString>

namespace DriveDesk {

// What the drive's channel assignment came to after the choices were written and read back.
struct ScopeChannelsOutcome
{
    ScopeAssignment assignment; // as read back; empty entries where it could not be read
    QString error;              // the first refusal or failure, in words; empty when all went well
    bool connectionFailed = false;
    bool refusedChoice = false; // a choice was not allowed: nothing was sent
};

// What putting the sources a user chose on the scope channels writes: each chosen channel's
// source and set-mask parameter (ScopeAssignmentParameters), with the value for it.
struct ScopeChannelWrites
{
    struct Write
    {
        quint16 address = 0;
        qint32 raw = 0;
    };
    QList<Write> writes;
    QString error; // a choice refused: nothing may be sent
};

// choices[i]: what to assign to channel i, nothing to leave it alone. A source must be one of
// scopeSources(drive) and its set mask not 0, and the drive must have assignment parameters
// (an F5), or the writes are refused with why.
ScopeChannelWrites planScopeChannels(const DriveDescription &drive,
                                     const ScopeAssignment &choices);

// Reads every channel's assignment, so that a recording shows what the drive really delivers.
// Without assignment parameters (not an F5) it sends nothing: the assignment stays unknown.
class ScopeChannelsJob : public RequestJob<ScopeChannelsOutcome>
{
public:
    ScopeChannelsJob(Protocol protocol, const DriveDescription &drive);

private:
    void start() override;
    void readNext();
    void finish();

    const Protocol m_protocol;
    QList<quint16> m_reads;
    qsizetype m_nextRead = 0;
    std::array<std::optional<qint32>, 8> m_readValues{};
    ScopeChannelsOutcome m_outcome;
};

} // namespace DriveDesk
