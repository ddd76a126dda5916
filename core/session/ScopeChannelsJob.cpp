#include "ScopeChannelsJob.h"

#include "client/ValueRequests.h"
#include "parameters/ParameterId.h"

#include <QCoreApplication>

namespace DriveDesk {

ScopeChannelWrites planScopeChannels(const DriveDescription &drive,
                                     const ScopeAssignment &choices)
{
    ScopeChannelWrites planned;
    const bool anyChoice = std::any_of(choices.begin(), choices.end(),
                                       [](const auto &choice) { return choice.has_value(); });
    const std::optional<ScopeAssignmentParameters> parameters = scopeAssignmentParameters(drive);
    if (!parameters) {
        if (anyChoice)
            planned.error = QCoreApplication::translate(
                "DriveDesk::ScopeChannelsJob",
                "This drive has no channel-assignment parameters (Sy.16 to Sy.23): its channels "
                "are recorded as it has them assigned.");
        return planned;
    }
    const QList<const ParameterDescription *> sources = scopeSources(drive);
    for (std::size_t channel = 0; channel < choices.size(); ++channel) {
        const std::optional<ChannelAssignment> &choice = choices[channel];
        if (!choice)
            continue;
        if (choice->source != ChannelAssignment::kOff) {
            const bool permitted = std::any_of(
                sources.begin(), sources.end(),
                [&](const ParameterDescription *p) { return p->address == choice->source; });
            if (!permitted) {
                planned.error = QCoreApplication::translate(
                                    "DriveDesk::ScopeChannelsJob",
                                    "Channel %1: %2 may not be recorded (the drive does not "
                                    "permit it as process data).")
                                    .arg(channel + 1)
                                    .arg(ParameterId::format(quint16(choice->source), drive));
                break;
            }
        }
        if (choice->setMask == 0) {
            planned.error = QCoreApplication::translate("DriveDesk::ScopeChannelsJob",
                                                        "Channel %1: choose at least one set.")
                                .arg(channel + 1);
            break;
        }
        planned.writes << ScopeChannelWrites::Write { parameters->source[channel], choice->source }
                       << ScopeChannelWrites::Write { parameters->setMask[channel],
                                                      choice->setMask };
    }
    if (!planned.error.isEmpty())
        planned.writes.clear();
    return planned;
}

ScopeChannelsJob::ScopeChannelsJob(Protocol protocol, const DriveDescription &drive)
    : m_protocol(protocol)
{
    if (const std::optional<ScopeAssignmentParameters> parameters
        = scopeAssignmentParameters(drive))
        m_reads = parameters->all();
}

void ScopeChannelsJob::start()
{
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
