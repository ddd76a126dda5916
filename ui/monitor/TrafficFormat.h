#pragma once

#include "client/DriveClient.h"
#include "protocol/Codec.h"

#include <QCoreApplication>
#include <QStringList>

#include <memory>

namespace DriveDesk {

// One telegram as the monitor keeps it: the client's record and the protocol it was spoken in.
struct TrafficEntry
{
    TrafficRecord record;
    Protocol protocol = Protocol::Hsp5;
    // The parameters known when the telegram was captured: its meaning names them, whatever
    // drive or file comes later (null: ids from the address, raw values).
    std::shared_ptr<const DriveDescription> drive;
    // What the meaning column shows, once TrafficModel made it (on first use: a row never shown
    // costs nothing).
    QString meaning;
    bool described = false;
};

// How a telegram reads in the monitor, in its copies and in saved files. The view, the
// clipboard and the files all go through it, so they agree.
class TrafficFormat
{
    Q_DECLARE_TR_FUNCTIONS(TrafficFormat)
public:
    enum Field { Time, Direction, Bytes, Characters, Meaning, FieldCount };
    enum class Clock : quint8 { TimeOfDay, DateAndTime };

    static QString fieldName(Field field);
    // Local time: 12:04:31.250, or with the date for files: 2024-05-17 12:04:31.250.
    static QString time(qint64 msecsSinceEpoch, Clock clock = Clock::TimeOfDay);
    // "→ drive", "← drive", "error".
    static QString direction(TrafficRecord::Kind kind);
    // Upper-case hex, a space between bytes: "02 47 31".
    static QString hex(const QByteArray &bytes);
    // The characters of an ASCII protocol, control characters named: "<STX>G1..<ETX>".
    // Empty for HSP5, whose bytes are binary.
    static QString characters(const TrafficEntry &entry);
    // Whether the protocol's telegrams are characters worth showing as text.
    static bool isAscii(Protocol protocol);

    // What a telegram means, in the installed language: a request as what it asks for, an
    // answer as the answer to its request ("ru.13 Actual load: 57 %"), an error as the
    // client's note, and the request it is about. `drive` names the parameters; it may be null.
    static QString meaning(const TrafficEntry &entry, const DriveDescription *drive);
    // Every field of an entry, in Field order; line breaks in the meaning become spaces. The
    // meaning is the entry's own where the model made it, otherwise made with its drive.
    static QStringList fields(const TrafficEntry &entry, Clock clock);
    // The visible fields joined by tabs: one line of a copy or a text file.
    static QString tabSeparated(const QStringList &fields);
};

} // namespace DriveDesk
