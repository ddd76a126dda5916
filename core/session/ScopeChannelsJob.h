#pragma once

#include "client/RequestJob.h"
#include "protocol/Codec.h"
#include "session/ScopeAssignment.h"

#include <QString>

namespace DriveDesk {

// What the drive's channel assignment came to after a ScopeChannelsJob.
struct ScopeChannelsOutcome
{
    ScopeAssignment assignment; // as read back; empty entries where it could not be read
    QString error;              // the first refusal or failure, in words; empty when all went well
    bool connectionFailed = false;
    bool refusedChoice = false; // a choice was not allowed: nothing was sent
};

// Puts the sources a user chose on the scope channels and reads every channel's assignment
// back, so that a recording shows what the drive really delivers. Without assignment
// parameters (not an F5) it sends nothing: the channels stay as the drive has them.
class ScopeChannelsJob : public RequestJob<ScopeChannelsOutcome>
{
public:
    // choices[i]: what to assign to channel i, nothing to leave it alone. A source must be one
    // of scopeSources(drive) and its set mask not 0, or the job refuses before it sends anything.
    ScopeChannelsJob(Protocol protocol, const DriveDescription &drive, ScopeAssignment choices);

private:
    void start() override;
    void writeNext();
    void readBack();
    void readNext();
    void finish();

    struct Write
    {
        quint16 address = 0;
        bool setProgrammable = false;
        qint32 raw = 0;
    };

    const Protocol m_protocol;
    std::optional<ScopeAssignmentParameters> m_parameters;
    QList<Write> m_writes;
    qsizetype m_nextWrite = 0;
    QList<quint16> m_reads;
    qsizetype m_nextRead = 0;
    std::array<std::optional<qint32>, 8> m_readValues{};
    ScopeChannelsOutcome m_outcome;
};

} // namespace DriveDesk
