#pragma once

#include <QString>

namespace DriveDesk {

// Installs the user's language for every tr() of the program: Qt's own texts (qtbase_<code>
// from Qt's translations folder, where it has them) and DriveDesk's catalogue
// (":/i18n/drivedesk_<code>.qm"). English loads a catalogue too: it holds the plural forms of
// the "%n ...(s)" texts. Call once on the main thread after the QCoreApplication exists.
// Returns false when DriveDesk's catalogue for `code` is missing: the texts stay as written.
bool installTranslations(const QString &code);

} // namespace DriveDesk
