#include "PasswordLevelJob.h"

#include "client/ValueRequests.h"

namespace DriveDesk {

PasswordLevelJob::PasswordLevelJob(Protocol protocol, std::optional<qint32> password)
    : m_protocol(protocol)
    , m_password(password)
{ }

void PasswordLevelJob::start()
{
    if (!m_password)
        return readLevel();
    sink().submit(ValueRequests::writeStandard(m_protocol, kPasswordParameterAddress, *m_password),
                  [this](const Reply &reply) {
                      if (!reply.ok()) {
                          m_outcome.error = reply.message();
                          return finish();
                      }
                      m_outcome.passwordAccepted = true;
                      if (isCancelled())
                          return finish();
                      readLevel();
                  });
}

void PasswordLevelJob::readLevel()
{
    sink().submit(ValueRequests::readStandard(m_protocol, kPasswordParameterAddress),
                  [this](const Reply &reply) {
                      if (const auto *value = reply.data<ParameterValue>()) {
                          m_outcome.readValue = value->value;
                          m_outcome.level = passwordLevelFromReadValue(value->value);
                      } else {
                          m_outcome.error = reply.message();
                      }
                      finish();
                  });
}

void PasswordLevelJob::finish()
{
    promise().addResult(m_outcome);
    end();
}

} // namespace DriveDesk
