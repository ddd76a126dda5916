#pragma once

#include "link/ConnectionSettings.h"

#include <QCoreApplication>
#include <QStringList>

#include <optional>

namespace DriveDesk {

// What `drivedesk` was started with: the drive to connect to or the parameter file to open (if
// any) and the UI language. The connection options are those of drivedesk-cli, checked the same
// way.
struct StartupOptions
{
    std::optional<ConnectionSettings> connection; // --connect given
    QString parameterFile; // --open given: shown with no drive
    QString journalPath; // --journal given: the journal the window writes and shows
    std::optional<Language> language; // --language given
    bool help = false;
    QString error; // names the bad argument; empty when the arguments made sense

    static StartupOptions parse(const QStringList &arguments);
    static QString usage();

    // The UI language: --language, else the one chosen in the menu (QSettings "language"),
    // else German on a German system, else English.
    Language uiLanguage() const;
};

// The tr() context of StartupOptions.
class StartupText
{
    Q_DECLARE_TR_FUNCTIONS(DriveDesk::StartupOptions)
};

} // namespace DriveDesk
