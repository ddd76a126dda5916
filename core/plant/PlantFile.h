#pragma once

#include "link/ConnectionSettings.h"
#include "protocol/Codec.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// One line to drives: where it is, how it speaks, and on a DIN bus which drives are on it.
struct PlantLink
{
    static constexpr int kMaxNameLength = 64;

    QString name;     // unique in the plant, a safe part of a file name
    QString connect;  // as --connect takes it, kept as written: tcp:HOST:PORT, serial:DEVICE, sim
    Protocol protocol = Protocol::Hsp5;
    std::optional<qint32> baudRate;
    // DIN66019(II): the drive addresses on the bus; empty when they are to be searched for.
    // HSP5 is point to point: always empty.
    QList<int> addresses;

    // How to reach the drive at `address` (ignored for HSP5), as --connect, --protocol,
    // --address and --baud would give it; a `sim` link simulates the drives at `addresses`.
    ConnectionSettings settings(int address) const;

    bool operator==(const PlantLink &other) const;
};

// A machine of many drives: its name and the links its drives hang on.
struct Plant
{
    QString name;
    QList<PlantLink> links;

    PlantLink *link(const QString &name);
    const PlantLink *link(const QString &name) const;

    bool operator==(const Plant &) const = default;
};

// The plant file: a Plant as JSON ("drivedesk-plant", version 1), described in docs/plant.md.
// Reading refuses anything it does not understand, naming the file, line and column, as the
// parameter file's reader does.
class PlantFile
{
    Q_DECLARE_TR_FUNCTIONS(PlantFile)
public:
    static constexpr int kVersion = 1;
    static constexpr qint64 kMaxFileSize = 1024 * 1024;
    static const QString kFormat; // "drivedesk-plant"

    // Pretty-printed, keys in a fixed order, so that a rewrite changes only what changed.
    static QByteArray toJson(const Plant &plant);
    // Nothing, with the place, the reason and where it is in the text ("links[1].protocol:
    // unknown protocol 'x': ... (line 16, column 13)"), for anything that is not a valid plant
    // file. load() puts the file's path in front.
    static std::optional<Plant> fromJson(const QByteArray &json, QString *error = nullptr);

    // Writes through QSaveFile: on failure the file at `path` is left as it was.
    static bool save(const QString &path, const Plant &plant, QString *error = nullptr);
    static std::optional<Plant> load(const QString &path, QString *error = nullptr);

    // Why `name` cannot name a link (it goes into file names), or nothing when it can.
    static std::optional<QString> linkNameProblem(const QString &name);
};

} // namespace DriveDesk
