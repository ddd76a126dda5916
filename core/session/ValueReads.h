#pragma once

#include "client/RequestJob.h"
#include "protocol/Codec.h"
#include "parameters/DriveDescription.h"
#include "parameters/PasswordLevel.h"

#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// One value to read: service 0 for one set of a set-programmable parameter, service 1 set 0 for
// the one value of any other parameter, as the drive scan reads them.
struct ValueRead
{
    quint16 address = 0;
    int set = 0;
    bool perSet = false;
};

// What became of one read.
struct ValueReading
{
    ValueRead read;
    std::optional<qint32> value; // what the drive holds; empty when the read failed
    QString reason;              // why it failed, in words
    bool connectionFailed = false; // no answer at all: the batch stopped here
};

// What a batch of readings came to besides its values: the reads the drive refused, and why the
// batch stopped when the connection failed. The window's refresh and polling both keep one.
struct ReadingsSummary
{
    QList<ValueReading> failures; // refused, in the order they came
    QString stopReason;           // the first connection failure, or empty

    // Takes one reading in; a value it carries is the caller's to use.
    void add(const ValueReading &reading);
};

// Every value of the parameter: one read per set, or the one value.
QList<ValueRead> valueReadsOf(const ParameterDescription &parameter);
// Every value the level lets be read, of the whole drive or of one group.
QList<ValueRead> readableValues(const DriveDescription &drive, PasswordLevel level);
QList<ValueRead> readableValues(const GroupDescription &group, PasswordLevel level);
// The values a change of level from `from` to `to` opens: readable at `to`, not at `from`.
QList<ValueRead> valuesOpenedBy(const DriveDescription &drive, PasswordLevel from,
                                PasswordLevel to);

// Reads a list of values. Result i is the reading of reads[i], reported as it comes; progress
// counts the reads done. A read the drive refuses is reported with its reason and the batch goes
// on; when the connection fails, that reading says so and the batch stops. A cancel drops the
// reads still on the client's queue.
class ReadValuesJob : public RequestJob<ValueReading>
{
public:
    ReadValuesJob(Protocol protocol, QList<ValueRead> reads);

    int total() const { return int(m_reads.size()); }

private:
    void start() override;
    void stopping() override;
    void sendMore();
    void handle(int index, const Reply &reply);

    const Protocol m_protocol;
    const QList<ValueRead> m_reads;
    qsizetype m_next = 0;
    int m_onTheWay = 0;
    int m_done = 0;
    bool m_stopped = false; // the connection failed
    bool m_sending = false;
};

} // namespace DriveDesk
