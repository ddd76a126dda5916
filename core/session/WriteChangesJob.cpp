#include "WriteChangesJob.h"

namespace DriveDesk {

WriteChangesJob::WriteChangesJob(Protocol protocol, QList<ValueChange> changes)
    : m_protocol(protocol)
    , m_changes(std::move(changes))
{
    promise().setProgressRange(0, total());
}

void WriteChangesJob::start()
{
    writeNext();
}

void WriteChangesJob::writeNext()
{
    if (isCancelled() || isStopRequested() || m_next >= m_changes.size())
        return end();
    const int index = int(m_next++);
    sendValueChange(sink(), m_protocol, m_changes.at(index),
                    [this, index](const WriteOutcome &outcome) {
                        promise().addResult(outcome, index);
                        promise().setProgressValue(index + 1);
                        if (outcome.connectionFailed)
                            return end();
                        writeNext();
                    });
}

} // namespace DriveDesk
