#pragma once

#include "client/RequestJob.h"
#include "session/ValueChange.h"

#include <QList>

namespace DriveDesk {

// Writes a list of changes one after the other, each read back; result i is the outcome of
// changes[i]. A lost connection stops the job. requestStop() sends nothing more and still
// reports the write on its way, so that every change without a result was never written.
// Copying a set and downloading a parameter file both write this way.
class WriteChangesJob : public RequestJob<WriteOutcome>
{
public:
    WriteChangesJob(Protocol protocol, QList<ValueChange> changes);

    int total() const { return int(m_changes.size()); }

private:
    void start() override;
    void writeNext();

    const Protocol m_protocol;
    const QList<ValueChange> m_changes;
    qsizetype m_next = 0;
};

} // namespace DriveDesk
