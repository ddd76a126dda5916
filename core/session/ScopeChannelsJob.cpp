#include "ScopeChannelsJob.h"

#include "client/ValueRequests.h"
#include "parameters/ParameterId.h"
#include "session/ValueChange.h"

#include <QCoreApplication>

namespace DriveDesk {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("ScopeChannelsJob", text);
}

} // namespace

ScopeChannelsJob::ScopeChannelsJob(Protocol protocol, const DriveDescription &drive,
                                   ScopeAssignment choices)
    : m_protocol(protocol)
    , m_parameters(scopeAssignmentParameters(drive))
{
    const bool anyChoice = std::any_of(choices.begin(), choices.end(),
                                       [](const auto &choice) { return choice.has_value(); });
    if (!m_parameters) {
        m_outcome.refusedChoice = anyChoice;
        if (anyChoice)
            m_outcome.error = tr("This drive has no channel-assignment parameters (Sy.16 to "
                                 "Sy.23): its channels are recorded as it has them assigned.");
        return;
    }
    const QList<const ParameterDescription *> sources = scopeSources(drive);
    for (std::size_t channel = 0; channel < choices.size() && m_outcome.error.isEmpty();
         ++channel) {
        const std::optional<ChannelAssignment> &choice = choices[channel];
        if (!choice)
            continue;
        if (choice->source != ChannelAssignment::kOff) {
            const bool permitted = std::any_of(
                sources.begin(), sources.end(),
                [&](const ParameterDescription *p) { return p->address == choice->source; });
            if (!permitted) {
                m_outcome.error
                    = tr("Channel %1: %2 may not be recorded (the drive does not permit it as "
                         "process data).")
                          .arg(channel + 1)
                          .arg(ParameterId::format(quint16(choice->source), drive));
                break;
            }
        }
        if (choice->setMask == 0) {
            m_outcome.error = tr("Channel %1: choose at least one set.").arg(channel + 1);
            break;
        }
        const quint16 sourceParameter = m_parameters->source[channel];
        const quint16 maskParameter = m_parameters->setMask[channel];
        const ParameterDescription *source = drive.find(sourceParameter);
        const ParameterDescription *mask = drive.find(maskParameter);
        m_writes << Write{sourceParameter, source && source->isSetProgrammable(), choice->source}
                 << Write{maskParameter, mask && mask->isSetProgrammable(), choice->setMask};
    }
    m_outcome.refusedChoice = !m_outcome.error.isEmpty();
    m_reads = m_parameters->all();
}

void ScopeChannelsJob::start()
{
    if (!m_outcome.error.isEmpty() || !m_parameters)
        return finish();
    writeNext();
}

void ScopeChannelsJob::writeNext()
{
    if (isCancelled() || isStopRequested())
        return finish();
    if (m_nextWrite >= m_writes.size())
        return readBack();
    const Write write = m_writes.at(m_nextWrite++);
    ValueChange change;
    change.address = write.address;
    change.setProgrammable = write.setProgrammable;
    change.steps << WriteStep{0, write.raw, false}; // the active set: the one the drive uses
    sendValueChange(sink(), m_protocol, change, [this](const WriteOutcome &outcome) {
        if (!outcome.ok()) {
            m_outcome.error = outcome.error;
            m_outcome.connectionFailed = outcome.connectionFailed;
            // What did reach the drive is still read back, where the link allows.
            if (outcome.connectionFailed)
                return finish();
            return readBack();
        }
        writeNext();
    });
}

void ScopeChannelsJob::readBack()
{
    m_nextRead = 0;
    readNext();
}

void ScopeChannelsJob::readNext()
{
    if (isCancelled())
        return finish();
    if (m_nextRead >= m_reads.size())
        return finish();
    const qsizetype index = m_nextRead++;
    sink().submit(ValueRequests::readStandard(m_protocol, m_reads.at(index)),
                  [this, index](const Reply &reply) {
                      if (const auto *value = reply.data<ParameterValue>()) {
                          m_readValues[std::size_t(index)] = value->value;
                      } else {
                          if (m_outcome.error.isEmpty())
                              m_outcome.error = reply.message();
                          if (reply.isConnectionFailure()) {
                              m_outcome.connectionFailed = true;
                              return finish();
                          }
                      }
                      readNext();
                  });
}

void ScopeChannelsJob::finish()
{
    if (hasEnded())
        return;
    for (std::size_t channel = 0; channel < m_outcome.assignment.size(); ++channel) {
        const std::optional<qint32> source = m_readValues[2 * channel];
        const std::optional<qint32> mask = m_readValues[2 * channel + 1];
        if (source && mask)
            m_outcome.assignment[channel] = ChannelAssignment{*source, quint8(*mask)};
    }
    promise().addResult(m_outcome);
    end();
}

} // namespace DriveDesk
