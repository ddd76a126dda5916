// How a scan decides that an answer is the drive's truth. On a clean line the first answer is
// kept: reading everything twice would halve the speed of every scan. Once the client has noted
// an error on the line (a checksum or framing error, a timeout, an answer that did not match),
// a flipped bit may also have slipped past the checksum (docs/client.md): from then on an answer
// counts once two reads of it agree, and what was kept before is read once more. An answer that
// cannot be true (ReplyCheck's implausibleAnswer()) is read again, whatever the line.
#include "DriveScanner.h"

#include "ReplyCheck.h"
#include "parameters/ParameterProperties.h"

namespace DriveDesk {

namespace {

// Reads of one request before it counts as unsettled: two that agree are needed, a third
// and a fourth may replace a garbled one.
constexpr int kMaxReads = 4;

bool sameAnswer(const Reply &a, const Reply &b)
{
    if (a.status != b.status || a.ack() != b.ack())
        return false;
    return a.status != Reply::Status::Ok || a.response.data == b.response.data;
}

} // namespace

void DriveScanner::checkLine()
{
    if (m_lineShowedErrors || m_sink.lineErrors() == m_lineErrorsAtStart)
        return;
    m_lineShowedErrors = true;
    // Kept while the line seemed clean, but the flip that slipped through may have come first.
    for (Kept &kept : m_kept) {
        auto request = std::make_shared<QueuedRequest>();
        request->telegram = kept.telegram;
        request->what = kept.what;
        request->answers.push_back(kept.reply);
        request->reads = 1;
        request->recheck = true;
        request->handle = [this, what = kept.what, first = kept.reply,
                           valueOf = kept.valueOf](const Reply &settled) {
            if (sameAnswer(settled, first))
                return;
            // A live value (the drive changes it by itself) read again shows another value:
            // that says nothing against the line. It is left unconfirmed, as one that never
            // agreed (failValue()), and holds up no backup or verify: it is no setting.
            if (valueOf && leaveLiveValueUnconfirmed(valueOf->first, valueOf->second, first))
                return;
            m_state.problems.append(
                tr("%1: not confirmed when read again on a line with errors").arg(what));
        };
        m_queue.push_back(std::move(request));
        ++m_enqueued;
    }
    m_kept.clear();
}

bool DriveScanner::leaveLiveValueUnconfirmed(quint8 page, quint8 number, const Reply &first)
{
    ScanParameter &parameter = m_state.parameter(page, number);
    const ParameterProperties properties(parameter.description.properties1,
                                         parameter.description.properties2);
    if (!properties.isChangedByInverter())
        return false;
    const auto *read = first.request.as<ParameterValue>();
    const quint8 sets = read && first.request.service == Service::ParameterValue
        ? read->set
        : quint8(0x01);
    for (int set = 0; set < kParameterSets; ++set) {
        if (sets & (1u << set))
            parameter.description.values[std::size_t(set)].reset();
    }
    parameter.errors.append(tr("%1: not confirmed: the drive changes it by itself, and on a line "
                               "with errors no two reads agreed")
                                .arg(tr("value")));
    return true;
}

void DriveScanner::settle(const Queued &request, const Reply &reply)
{
    if (!reply.isAnswer()) {
        // The client has asked as often as it may: a request that got no answer at all is
        // an error. One that already has an answer may still find a second to agree with it.
        if (!request->answers.empty() && request->reads < kMaxReads)
            return readAgain(request);
        if (request->answers.empty()) {
            request->disagreed = false;
            return unsettled(request, reply);
        }
    } else {
        QString why = reply.ok() ? implausibleAnswer(reply.response) : QString();
        if (why.isEmpty() && request->check)
            why = request->check(reply);
        if (!why.isEmpty()) {
            request->implausible.append(why);
        } else if (!m_lineShowedErrors) {
            m_kept.push_back({ request->telegram, request->what, reply, request->valueOf });
            return deliver(*request, reply);
        } else {
            for (const Reply &earlier : request->answers) {
                if (sameAnswer(earlier, reply))
                    return deliver(*request, reply);
            }
            request->answers.push_back(reply);
        }
        if (request->reads < kMaxReads)
            return readAgain(request);
    }
    // Read as often as it may be: what came back never agreed, or could not be true.
    request->disagreed = request->implausible.isEmpty();
    Reply failure = reply;
    failure.status = Reply::Status::Timeout;
    failure.attempts = request->reads;
    failure.detail = request->implausible.isEmpty()
        ? tr("the answers did not agree")
        : tr("implausible answer: %1").arg(request->implausible.constLast());
    unsettled(request, failure);
}

// Noise comes in bursts (a motor starting, a contactor): what one round could not settle often
// settles later. The second round's failure is the item's error.
void DriveScanner::unsettled(const Queued &request, const Reply &failure)
{
    if (request->secondRound)
        return deliver(*request, failure);
    request->secondRound = true;
    request->reads = 0;
    m_later.push_back({ request, failure });
}

bool DriveScanner::startSecondRound()
{
    if (m_later.empty())
        return false;
    for (Unsettled &item : m_later) {
        m_queue.push_back(std::move(item.request));
        ++m_enqueued;
    }
    m_later.clear();
    return true;
}

void DriveScanner::deliverUnsettled()
{
    std::vector<Unsettled> later;
    later.swap(m_later);
    for (const Unsettled &item : later)
        deliver(*item.request, item.failure);
}

void DriveScanner::deliver(const QueuedRequest &request, const Reply &reply)
{
    // Counted before the handler runs: it enqueues what the answer leads to.
    const Service service = request.telegram.service;
    if (!request.recheck && service == Service::Properties)
        ++m_values.answered;
    else if (!request.recheck && service == Service::PlaintextIndices)
        ++m_plaintexts.answered;
    if (request.disagreed && !reply.isAnswer()) {
        Reply unconfirmed = reply;
        unconfirmed.disagreed = true;
        request.handle(unconfirmed);
        return;
    }
    request.handle(reply);
}

void DriveScanner::readAgain(const Queued &request)
{
    // First in line: the item settles before what depends on it is asked.
    m_queue.push_front(request);
    ++m_enqueued;
}

QString DriveScanner::implausibleRead(quint8 page, quint8 number, const Reply &reply) const
{
    const ScanParameter &scanned = m_state.groups.at(page).parameters.at(number);
    if (!scanned.limitsKnown)
        return {};
    if (const auto *value = reply.data<ParameterValue>())
        return implausibleValue(scanned.description, value->value);
    if (const auto *value = reply.data<DefaultValue>())
        return implausibleValue(scanned.description, value->value);
    return {};
}

} // namespace DriveDesk
