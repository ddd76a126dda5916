#pragma once

#include "TrafficFormat.h"

#include <QCoreApplication>
#include <QList>

namespace DriveDesk {

// Saves telegrams of the monitor to a file: CSV where the name ends in .csv, tab-separated
// text otherwise; both UTF-8 with a header line and the date in each time. Written through
// QSaveFile, so a failed save leaves any earlier file as it was and no partial one behind.
class TrafficFile
{
    Q_DECLARE_TR_FUNCTIONS(TrafficFile)
public:
    enum class Format : quint8 { Text, Csv };

    static Format formatFor(const QString &path);
    // False, with the reason in *error, when the file cannot be written.
    static bool save(const QString &path, const QList<TrafficEntry> &entries,
                     QString *error = nullptr);
};

} // namespace DriveDesk
