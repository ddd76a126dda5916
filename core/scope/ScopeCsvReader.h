#pragma once

#include "ScopeSeries.h"

#include <QList>
#include <QString>

namespace DriveDesk {

// Reads a scope CSV export (writeScopeCsv(), docs/scope.md "Exporting as CSV") back: one
// series a channel column, titled and in the unit its header gives ("ru.03 Actual frequency
// [Hz]": title "ru.03 Actual frequency", unit "Hz"), its times the file's "Time [ms]" (ms since
// the recording's first sample). An empty field (a value the scaling could not show) leaves
// that sample out of its column. Comma-separated, '.' as decimal point, header fields quoted
// as RFC 4180 asks; CRLF or LF line ends; a UTF-8 byte-order mark is passed over. The samples
// end at the first empty line (the measurements section follows it, scopeCsvMeasurements()).
//
// False, with `error` naming the file and the fault (cannot be read, not a scope CSV export,
// a line with another number of fields than the header, a field that is no number and where,
// a time earlier than the line's before), and `columns` untouched.
bool readScopeCsv(const QString &path, QList<ScopeSeries> &columns, QString *error = nullptr);

} // namespace DriveDesk
