#pragma once

#include <QString>
#include <QStringList>

namespace DriveDesk {

struct ScopeRecording;

// Loads a recording file (.ddscope, written by ScopeFileWriter) to view it offline.
//
// On success `out` is the file's recording (its channels, start, source and samples) and
// `warnings` lists what was left out: an incomplete last sample, as a recording cut off by a
// crash leaves it. On failure `error` says why with the file's name (not a scope file, a newer
// format, a damaged header and its field, samples out of order and where, unreadable) and
// `out` is untouched: the file is loaded aside and taken over only when complete.
bool readScopeFile(const QString &path, ScopeRecording &out, QString *error = nullptr,
                   QStringList *warnings = nullptr);

} // namespace DriveDesk
