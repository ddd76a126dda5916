#pragma once

#include "DriveDescription.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace DriveDesk {

// A drive's values for a spreadsheet: one row per parameter with its id, name, unit and the
// value of each set as the drive shows it (plaintext, or the scaled number without its unit),
// "?" where a value was not read, empty for the sets a parameter without sets does not have.
// Comma-separated, fields quoted where they hold a comma, a quote or a line break (RFC 4180),
// UTF-8 with CRLF line ends. Numbers follow the default QLocale's decimal separator, so the
// command line (C locale) writes "12.50".
QByteArray parametersAsCsv(const DriveDescription &drive);
// The same, saved to a file whole or not at all (SavedFile).
bool saveParametersAsCsv(const QString &path, const DriveDescription &drive,
                         QString *error = nullptr);

// One CSV record (RFC 4180) without its line end: the fields joined by commas, each quoted
// where it holds a comma, a quote or a line break. The telegram monitor's CSV files use it too.
QString csvRecord(const QStringList &fields);

} // namespace DriveDesk
