#include "DriveSearch.h"

#include "ClientTiming.h"
#include "ClientWorker.h"

#include <algorithm>

namespace DriveDesk {

namespace {

constexpr int kLastDriveAddress = 239;
// The longest answer a probe may get (DIN66019II service 0: STX G IID 8 digits ETX BCC),
// on top of the request itself.
constexpr int kProbeAnswerCharacters = 13;

} // namespace

DriveSearch::DriveSearch(ClientWorker &worker, int first, int last, quint16 probeAddress,
                         std::shared_ptr<QPromise<QList<int>>> promise)
    : QObject(&worker)
    , m_worker(worker)
    , m_owner(worker.newOwner())
    , m_probeAddress(probeAddress)
    , m_promise(std::move(promise))
{
    if (worker.settings().protocol == Protocol::Hsp5) {
        m_addresses.append(worker.settings().driveAddress);
    } else {
        for (int address = std::max(first, 0); address <= std::min(last, kLastDriveAddress);
             ++address)
            m_addresses.append(address);
    }
    m_total = int(m_addresses.size());
    if (m_addresses.isEmpty()) {
        m_problem = tr("the addresses %1..%2 hold no drive address (drives are 0..239)")
                        .arg(first)
                        .arg(last);
    }
}

void DriveSearch::start()
{
    if (m_addresses.isEmpty()) {
        m_promise->setProgressRange(0, 1);
        m_promise->setProgressValueAndText(1, m_problem);
        finish();
        return;
    }
    m_promise->setProgressRange(0, m_total);
    probeNext();
}

void DriveSearch::cancel()
{
    if (m_finished)
        return;
    m_worker.cancelOwner(m_owner);
    finish();
}

void DriveSearch::probeNext()
{
    if (m_finished)
        return;
    if (m_addresses.isEmpty()) {
        finish();
        return;
    }
    const int address = m_addresses.takeFirst();
    const Service service = m_worker.settings().protocol == Protocol::Din66019
                                ? Service::Legacy
                                : Service::ParameterValue;
    Telegram probe = Telegram::request(service, Access::Read, ParameterValue{m_probeAddress, 1, 0});
    probe.driveAddress = address;

    RequestOptions options;
    options.owner = m_owner;
    options.retries = 0;
    Telegram onTheWire = probe; // as the worker will send it, for its length
    onTheWire.operatorInvoke = 1;
    const int requestCharacters = int(m_worker.codec().encode(onTheWire).size());
    options.timeoutMs = std::min(probeTimeoutMs(m_worker.settings(), ClientOptions{},
                                                requestCharacters + kProbeAnswerCharacters),
                                 m_worker.answerTimeoutMs());
    m_worker.submitRequest(probe, options, [this, address](const Reply &reply, bool heard) {
        onProbed(address, reply, heard);
    });
}

void DriveSearch::onProbed(int address, const Reply &reply, bool heard)
{
    if (m_finished)
        return;
    switch (reply.status) {
    case Reply::Status::Cancelled:
    case Reply::Status::LinkLost:
    case Reply::Status::NotConnected:
    case Reply::Status::Unsupported:
        m_promise->setProgressValueAndText(m_total - int(m_addresses.size()),
                                           tr("drive %1: %2").arg(address).arg(reply.message()));
        finish();
        return;
    default:
        break;
    }
    const bool answered = reply.status == Reply::Status::Ok
                          || reply.status == Reply::Status::Refused || heard;
    if (answered)
        m_found.append(address);
    m_promise->setProgressValueAndText(m_total - int(m_addresses.size()),
                                       answered ? tr("drive %1 answered").arg(address)
                                                : tr("no drive at %1").arg(address));
    probeNext();
}

void DriveSearch::finish()
{
    if (m_finished)
        return;
    m_finished = true;
    m_promise->addResult(m_found);
    m_promise->finish();
    deleteLater();
}

} // namespace DriveDesk
