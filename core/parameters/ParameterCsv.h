#pragma once

#include "DriveDescription.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace DriveDesk {

// How a CSV file separates its fields and names its columns.
struct CsvStyle
{
    QChar separator = QLatin1Char(',');
    // The header in the installed language (tr()); otherwise the documented English one.
    bool translatedHeader = false;
    // UTF-8's byte order mark first: a spreadsheet that sees none reads the bytes in the
    // system's code page ("Â°C" for "°C").
    bool byteOrderMark = false;

    // As a spreadsheet of the default QLocale reads it: ';' where the decimal separator is a
    // comma (German), ',' elsewhere; the header in the installed language; the byte order
    // mark. The window's export.
    static CsvStyle forSpreadsheet();
};

// A drive's values for a spreadsheet: one row per parameter with its id, name, unit and the
// value of each set as the drive shows it (plaintext, or the scaled number without its unit),
// "?" where a value was not read, empty for the sets a parameter without sets does not have.
// Fields separated by the style's separator (',' by default) and quoted where they hold it, a
// quote or a line break (RFC 4180), UTF-8 with CRLF line ends. Numbers follow the default
// QLocale's decimal separator, so the command line (C locale, the default style) writes
// "id,name,unit,set 0,..." and "12.50".
QByteArray parametersAsCsv(const DriveDescription &drive, const CsvStyle &style = {});
// The same, saved to a file whole or not at all (SavedFile).
bool saveParametersAsCsv(const QString &path, const DriveDescription &drive,
                         QString *error = nullptr, const CsvStyle &style = {});

// One CSV record (RFC 4180) without its line end: the fields joined by the separator, each
// quoted where it holds the separator, a quote or a line break. The telegram monitor's CSV
// files use it too.
QString csvRecord(const QStringList &fields, QChar separator = QLatin1Char(','));

} // namespace DriveDesk
