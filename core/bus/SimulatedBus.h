#pragma once

#include "FaultInjector.h"
#include "link/ConnectionSettings.h"
#include "protocol/Codec.h"

#include <QByteArray>
#include <QByteArrayView>

#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace DriveDesk {

class SimulatedDrive;

// What the bus did, for tests and benchmarks. Bytes are counted as sent, before faults.
struct BusCounters {
    qint64 bytesToDrive = 0;   // sent by the operator
    qint64 bytesFromDrive = 0; // sent by the drives: replies and unsolicited requests
    int requests = 0;          // requests decoded, whoever they were for
    int replies = 0;           // telegrams the drives answered
    int unanswered = 0;        // requests no drive answers: no selection, broadcast, unknown drive
    int decodeErrors = 0;      // broken or garbled input, answered or not
    int partialDrops = 0;      // incomplete telegrams dropped after an idle gap on the line
    int framingLosses = 0;     // HSP5: requests of a service the drive cannot frame
    qint64 unframedBytes = 0;  // HSP5: bytes ignored after a framing loss until a quiet line
    int unexpected = 0;        // telegrams from the operator the drives cannot place
    int encodeFailures = 0;    // answers the codec could not express (reported as warnings)
    // Injected faults.
    int corruptedBytes = 0;
    int flippedBytes = 0; // unflagged flips
    int droppedBytes = 0;
    int delayedReplies = 0;
    int busyReplies = 0;
    int unsolicitedRequests = 0; // HSP5 requests the inverter started
    int unsolicitedAnswers = 0;  // the operator's answers to them, consumed
    qint64 ignoredWhileSilent = 0; // bytes from the operator no drive took: the bus was silent
};

// One telegram on its way from the drives to the operator. Times in ns on the bus clock:
// the first byte goes on the line at startNs, the last one has arrived at dueNs.
struct BusTransmission {
    QByteArray bytes; // as the operator receives them, faults included
    QList<qsizetype> lineErrors; // the operator's UART flagged a character before these indices
    qint64 startNs = 0;
    qint64 dueNs = 0;
};

// One or several simulated drives on a byte stream. Bytes from the operator go through a
// drive-side decoder to the addressed drive; its answer is encoded and scheduled on the line
// according to SimulationOptions (latency, pacing at the baud rate, injected faults).
// Pure bookkeeping: the caller supplies the time; BusClock runs it in real time.
// HSP5 is point to point (the first drive answers) and full duplex (each direction has its own
// timeline); a request the drive cannot frame costs it its step until the line is quiet. DIN66019(II) is multi-drop on one shared line: the EOT selection picks the drive.
class SimulatedBus
{
public:
    SimulatedBus(Protocol protocol, const SimulationOptions &options);
    ~SimulatedBus();
    SimulatedBus(const SimulatedBus &) = delete;
    SimulatedBus &operator=(const SimulatedBus &) = delete;

    Protocol protocol() const { return m_protocol; }
    const SimulationOptions &options() const { return m_options; }

    // Bytes from the operator, handed over at nowNs.
    void receive(QByteArrayView bytes, qint64 nowNs);

    // Transmissions not yet taken, in the order they go on the line.
    const std::deque<BusTransmission> &scheduled() const { return m_scheduled; }
    std::optional<qint64> nextDueNs() const;
    // The bytes of every transmission due at nowNs, in order, and where the operator's UART
    // flagged a character (indices into the result, see BusTransmission).
    QByteArray takeDue(qint64 nowNs, QList<qsizetype> *lineErrors = nullptr);

    // A frozen drive (a fault injected at run time): while silent, the drives take nothing
    // from the line and answer nothing, and the line itself stays open. Answers already on
    // their way still arrive. Coming back, the drives start on a fresh telegram.
    void setSilent(bool silent);
    bool isSilent() const { return m_silent; }

    // A new operator on the line: drops partial input, pending output and the selection.
    // The drives keep their state.
    void resetLine();

    const BusCounters &counters() const { return m_counters; }
    int driveCount() const { return int(m_stations.size()); }
    SimulatedDrive &drive(int index);
    // DIN66019(II): the drive address selected now, -1 for none.
    int selection() const { return m_selection; }

    // Time on the line for `count` characters back to back (0 when not paced), rounded up to ns.
    qint64 lineTimeNs(qint64 count) const;

private:
    struct Station {
        std::unique_ptr<SimulatedDrive> drive;
        int address = 0;
        Ack multicastResult = Ack::Ok; // DIN: outcome of the last broadcast/group write
    };

    void handle(const Decoded &item, qint64 endNs);
    void followSelection(int driveAddress, bool closesSelection);
    void handleHsp5(const Telegram &telegram, qint64 endNs);
    void handleDin(const Telegram &telegram, qint64 endNs);
    void handleError(const DecodeError &error, const QByteArray &broken, qint64 endNs);
    Telegram answer(Station &station, const Telegram &request, qint64 endNs);
    std::optional<Telegram> errorAnswer(const DecodeError &error, const QByteArray &broken) const;
    QByteArray brokenBytes(const DecodeError &error) const;
    static Telegram statusAnswer(Ack result);
    qint64 readyTime(qint64 endNs);
    void sendUnsolicited(const Telegram &request, qint64 readyNs);
    // Encodes and schedules; returns the encoded bytes (before faults), empty on failure.
    QByteArray transmit(const Telegram &telegram, qint64 readyNs);
    Station *station(int address);
    qint64 idleGapNs() const;

    // One direction of the line. Characters follow each other back to back from anchorNs on;
    // their times are computed from the count since the anchor, so no rounding adds up.
    struct Timeline {
        qint64 anchorNs = 0;
        qint64 characters = 0;
    };
    // Books count characters, not before readyNs; returns the index of the first since the anchor.
    qint64 occupy(Timeline &timeline, qint64 readyNs, qint64 count) const;
    qint64 timeOf(const Timeline &timeline, qint64 index) const
    {
        return timeline.anchorNs + lineTimeNs(index);
    }
    Timeline &inbound() { return m_protocol == Protocol::Hsp5 ? m_toDrive : m_line; }
    Timeline &outbound() { return m_protocol == Protocol::Hsp5 ? m_toOperator : m_line; }

    Protocol m_protocol;
    SimulationOptions m_options;
    std::unique_ptr<ProtocolCodec> m_codec;
    std::unique_ptr<FrameDecoder> m_decoder;
    std::vector<Station> m_stations; // in the order of options.driveAddresses
    BusCounters m_counters;
    FaultInjector m_faults;
    std::deque<BusTransmission> m_scheduled;

    // HSP5 is full duplex; DIN66019(II) has one line for both directions.
    Timeline m_toDrive;
    Timeline m_toOperator;
    Timeline m_line;
    qint64 m_lastArrivalNs = 0; // when the last byte from the operator was in
    // The latest bytes fed to the decoder, to read what a broken request was.
    QByteArray m_history;
    qint64 m_historyStart = 0; // stream position of m_history[0]
    qint64 m_fed = 0;          // bytes fed to the decoder so far
    bool m_selectionSent = false; // DIN: an EOT reached the decoder since the last selection
    // HSP5: a request of a service the drive does not know arrived. Its length follows from the
    // service alone, so the drive cannot tell where it ends: it ignores the line until it is
    // quiet, as a real drive must, and whatever was pipelined behind is lost.
    bool m_lostStep = false;
    int m_selection = -1;
    bool m_silent = false;
    quint8 m_inverterInvoke = 0;      // HSP5: INV-ID-FU of the last unsolicited request
    quint16 m_pendingUnsolicited = 0; // HSP5: bit n set = INV-ID-FU n awaits its answer
};

} // namespace DriveDesk
