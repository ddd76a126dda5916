#include "SimulatedBus.h"

#include "DinFraming.h"

#include "sim/SimulatedDrive.h"

#include <algorithm>

namespace DriveDesk {

using namespace DinFraming;

namespace {

constexpr quint16 kUnsolicitedLimitsAddress = 0x2101; // the address of seed 000's example
constexpr qint64 kMinimumIdleGapNs = 5'000'000;
constexpr qsizetype kHistoryKept = 512;

bool concerns(int selection, int address)
{
    if (selection == kBroadcastAddress)
        return true;
    return address / 16 == selection - kFirstGroupAddress;
}

} // namespace

SimulatedBus::SimulatedBus(Protocol protocol, const SimulationOptions &options)
    : m_protocol(protocol)
    , m_options(options)
    , m_codec(makeCodec(protocol, CodecOptions{options.hsp5Extensions}))
    , m_decoder(m_codec->makeDecoder(Role::Drive))
    , m_faults(options, m_codec->bitsPerCharacter() - 3, &m_counters) // 8E1 / 7E1: 8 / 7 data bits
{
    QList<int> addresses = options.driveAddresses;
    if (addresses.isEmpty())
        addresses = {1};
    // HSP5 is point to point: the first drive is the only one on the line.
    if (protocol == Protocol::Hsp5)
        addresses.resize(1);
    for (qsizetype i = 0; i < addresses.size(); ++i) {
        SimulatedDriveOptions driveOptions;
        driveOptions.address = addresses[i];
        driveOptions.parameterCount = options.parameterCount;
        driveOptions.seed = options.seed + quint32(i);
        driveOptions.metadataSeed = options.seed;
        driveOptions.displayTextAsCharacters = protocol != Protocol::Hsp5;
        if (options.unidentifiedAddresses.contains(addresses[i]))
            driveOptions.kind = SimulatedDriveKind::Unidentified;
        else if (options.otherKindAddresses.contains(addresses[i]))
            driveOptions.kind = SimulatedDriveKind::Other;
        Station station;
        station.address = addresses[i];
        station.drive = std::make_unique<SimulatedDrive>(driveOptions);
        m_stations.push_back(std::move(station));
    }
}

SimulatedBus::~SimulatedBus() = default;

SimulatedDrive &SimulatedBus::drive(int index)
{
    return *m_stations.at(std::size_t(index)).drive;
}

qint64 SimulatedBus::lineTimeNs(qint64 count) const
{
    if (!m_options.paced || m_options.baudRate <= 0)
        return 0;
    const qint64 bitNs = count * m_codec->bitsPerCharacter() * 1'000'000'000LL;
    return (bitNs + m_options.baudRate - 1) / m_options.baudRate;
}

qint64 SimulatedBus::occupy(Timeline &timeline, qint64 readyNs, qint64 count) const
{
    if (readyNs >= timeOf(timeline, timeline.characters)) {
        // The line was idle: a new run of characters starts.
        timeline.anchorNs = readyNs;
        timeline.characters = 0;
    }
    const qint64 first = timeline.characters;
    timeline.characters += count;
    return first;
}

qint64 SimulatedBus::idleGapNs() const
{
    return std::max(kMinimumIdleGapNs, lineTimeNs(10));
}

void SimulatedBus::setSilent(bool silent)
{
    if (silent == m_silent)
        return;
    m_silent = silent;
    if (!silent) {
        m_decoder->reset();
        m_lostStep = false;
    }
}

void SimulatedBus::receive(QByteArrayView bytes, qint64 nowNs)
{
    if (bytes.isEmpty())
        return;
    m_counters.bytesToDrive += bytes.size();
    if (m_silent) {
        m_counters.ignoredWhileSilent += bytes.size();
        return;
    }
    // The chunk occupies the line before any answer to it can start (DIN: a shared line).
    const Timeline &line = inbound();
    const qint64 first = occupy(inbound(), nowNs, bytes.size());
    const bool afterQuietLine = timeOf(line, first) - m_lastArrivalNs > idleGapNs();
    if (m_lostStep) {
        if (!afterQuietLine) {
            m_lastArrivalNs = timeOf(line, first + bytes.size());
            m_counters.unframedBytes += bytes.size();
            return;
        }
        m_lostStep = false; // in step again: this byte starts a telegram
    }
    // A drive forgets a partial telegram after a pause on the line, as after a lost character.
    if (m_decoder->buffered() > 0 && afterQuietLine) {
        m_decoder->reset();
        ++m_counters.partialDrops;
    }

    for (qsizetype i = 0; i < bytes.size(); ++i) {
        const qint64 arrivalNs = timeOf(line, first + i + 1);
        m_lastArrivalNs = arrivalNs;
        char byte = bytes[i];
        const FaultInjector::Fate fate = m_faults.pass(&byte);
        if (fate == FaultInjector::Fate::ParityError) {
            // The drive's UART flagged it: the telegram being received is dropped unanswered.
            m_decoder->reset();
            continue;
        }
        if (fate == FaultInjector::Fate::Lost)
            continue;
        if (m_protocol != Protocol::Hsp5 && byte == kEot)
            m_selectionSent = true;
        m_decoder->feed(QByteArrayView(&byte, 1));
        ++m_fed;
        m_history.append(byte);
        if (m_history.size() > 4 * kHistoryKept) {
            const qsizetype drop = m_history.size() - kHistoryKept;
            m_history.remove(0, drop);
            m_historyStart += drop;
        }
        while (std::optional<Decoded> item = m_decoder->next())
            handle(*item, arrivalNs);
        if (m_lostStep) {
            m_counters.unframedBytes += bytes.size() - i - 1;
            m_lastArrivalNs = timeOf(line, first + bytes.size());
            return;
        }
    }
}

std::optional<qint64> SimulatedBus::nextDueNs() const
{
    if (m_scheduled.empty())
        return std::nullopt;
    return m_scheduled.front().dueNs;
}

QByteArray SimulatedBus::takeDue(qint64 nowNs, QList<qsizetype> *lineErrors)
{
    QByteArray bytes;
    while (!m_scheduled.empty() && m_scheduled.front().dueNs <= nowNs) {
        if (lineErrors) {
            for (qsizetype at : m_scheduled.front().lineErrors)
                lineErrors->append(bytes.size() + at);
        }
        bytes += m_scheduled.front().bytes;
        m_scheduled.pop_front();
    }
    return bytes;
}

void SimulatedBus::resetLine()
{
    m_decoder->reset();
    m_scheduled.clear();
    m_toDrive = {};
    m_toOperator = {};
    m_line = {};
    m_lastArrivalNs = 0;
    m_history.clear();
    m_historyStart = m_fed;
    m_selectionSent = false;
    m_selection = -1;
    m_pendingUnsolicited = 0;
    m_lostStep = false;
}

void SimulatedBus::handle(const Decoded &item, qint64 endNs)
{
    const auto *error = std::get_if<DecodeError>(&item);
    if (m_protocol != Protocol::Hsp5)
        followSelection(error ? error->driveAddress : std::get<Telegram>(item).driveAddress,
                        !error || error->kind != DecodeError::Kind::UnexpectedByte);
    if (error && m_protocol == Protocol::Hsp5 && error->kind == DecodeError::Kind::UnknownService) {
        ++m_counters.decodeErrors;
        ++m_counters.framingLosses;
        m_lostStep = true;
        m_decoder->reset();
        return;
    }
    if (error) {
        ++m_counters.decodeErrors;
        handleError(*error, brokenBytes(*error), endNs);
        return;
    }
    const Telegram &telegram = std::get<Telegram>(item);
    if (m_protocol == Protocol::Hsp5)
        handleHsp5(telegram, endNs);
    else
        handleDin(telegram, endNs);
}

// The selection holds until the next EOT, whoever sends it. The decoder names the selection
// sent just before an item; an EOT that selected nobody (broken) still ends the old one.
// Garbage reported when an EOT arrives does not stand for the item that follows it.
void SimulatedBus::followSelection(int driveAddress, bool closesSelection)
{
    if (driveAddress >= 0) {
        m_selection = driveAddress;
        m_selectionSent = false;
    } else if (m_selectionSent && closesSelection) {
        m_selection = -1;
        m_selectionSent = false;
    }
}

void SimulatedBus::handleHsp5(const Telegram &telegram, qint64 endNs)
{
    if (telegram.isResponse()) {
        const quint16 bit = quint16(1u << (telegram.inverterInvoke & 0x0F));
        if (telegram.operatorInvoke == 0 && telegram.inverterInvoke != 0
            && (m_pendingUnsolicited & bit)) {
            m_pendingUnsolicited &= quint16(~bit);
            ++m_counters.unsolicitedAnswers;
        } else {
            ++m_counters.unexpected;
        }
        return;
    }
    ++m_counters.requests;
    const qint64 readyNs = readyTime(endNs);
    const Telegram reply = answer(m_stations.front(), telegram, endNs);
    if (m_faults.draw(m_options.unsolicitedRate))
        sendUnsolicited(telegram, readyNs);
    if (!transmit(reply, readyNs).isEmpty())
        ++m_counters.replies;
}

void SimulatedBus::handleDin(const Telegram &telegram, qint64 endNs)
{
    if (telegram.isResponse()) {
        ++m_counters.unexpected;
        return;
    }
    ++m_counters.requests;
    const int target = m_selection;
    if (target < 0) {
        ++m_counters.unanswered;
        return;
    }
    if (target >= kFirstGroupAddress) {
        // Nobody answers a group or broadcast; writes are carried out by every drive concerned
        // and their outcome waits for the status interrogation.
        ++m_counters.unanswered;
        if (!telegram.isWrite() || telegram.service == Service::StatusInterrogation)
            return;
        for (Station &station : m_stations) {
            if (concerns(target, station.address))
                station.multicastResult = answer(station, telegram, endNs).ack;
        }
        return;
    }
    Station *addressed = station(target);
    if (!addressed) {
        ++m_counters.unanswered;
        return;
    }
    const Telegram reply = telegram.service == Service::StatusInterrogation
                               ? statusAnswer(addressed->multicastResult)
                               : answer(*addressed, telegram, endNs);
    const QByteArray sent = transmit(reply, readyTime(endNs));
    if (sent.isEmpty())
        return;
    ++m_counters.replies;
    // A negative read answer ends in EOT, and an EOT on the line drops the selection.
    if (sent.endsWith(kEot))
        m_selection = -1;
}

qint64 SimulatedBus::readyTime(qint64 endNs)
{
    qint64 readyNs = endNs + qint64(m_options.replyLatencyUs) * 1000;
    if (m_faults.draw(m_options.delayRate)) {
        ++m_counters.delayedReplies;
        readyNs += qint64(m_options.delayMs) * 1'000'000;
    }
    return readyNs;
}

Telegram SimulatedBus::answer(Station &station, const Telegram &request, qint64 endNs)
{
    if (m_faults.draw(m_options.busyRate)) {
        ++m_counters.busyReplies;
        return request.response(Ack::Busy);
    }
    return station.drive->respond(request, endNs / 1'000'000);
}

// HSP5 is multi-master: the inverter may start a cycle of its own (INV-ID-OP 0), here a
// write of limits to the operator, which the operator answers.
void SimulatedBus::sendUnsolicited(const Telegram &request, qint64 readyNs)
{
    constexpr quint16 kEveryInvokeId = 0xFFFE; // bits 1..15
    if (m_pendingUnsolicited == kEveryInvokeId)
        return;
    do {
        m_inverterInvoke = quint8(m_inverterInvoke % 15 + 1);
    } while (m_pendingUnsolicited & (1u << m_inverterInvoke));

    quint16 address = kUnsolicitedLimitsAddress;
    if (const auto *value = request.as<ParameterValue>())
        address = value->address;
    Telegram unsolicited = Telegram::request(Service::Limits, Access::Write,
                                             ParameterLimits{address, 0x12345678, 0x23456789});
    unsolicited.operatorInvoke = 0;
    unsolicited.inverterInvoke = m_inverterInvoke;
    if (transmit(unsolicited, readyNs).isEmpty())
        return;
    m_pendingUnsolicited |= quint16(1u << m_inverterInvoke);
    ++m_counters.unsolicitedRequests;
}

QByteArray SimulatedBus::transmit(const Telegram &telegram, qint64 readyNs)
{
    QString error;
    const QByteArray bytes = m_codec->encode(telegram, &error);
    if (bytes.isEmpty()) {
        ++m_counters.encodeFailures;
        qWarning("simulated drive: cannot send %s: %s", qPrintable(describe(telegram)),
                 qPrintable(error));
        return bytes;
    }
    m_counters.bytesFromDrive += bytes.size();
    Timeline &line = outbound();
    const qint64 first = occupy(line, readyNs, bytes.size());
    BusTransmission transmission;
    transmission.startNs = timeOf(line, first);
    transmission.dueNs = timeOf(line, first + bytes.size());
    transmission.bytes = m_faults.pass(bytes, &transmission.lineErrors);
    m_scheduled.push_back(std::move(transmission));
    return bytes;
}

SimulatedBus::Station *SimulatedBus::station(int address)
{
    for (Station &candidate : m_stations) {
        if (candidate.address == address)
            return &candidate;
    }
    return nullptr;
}

} // namespace DriveDesk
