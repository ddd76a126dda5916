#pragma once

#include "ScopePreset.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

namespace DriveDesk {

struct DriveDescription;

// What kind of drive a preset is for: the drive's identification text (service 13) where it
// has one, else the raw values of the identification parameters that name its kind
// ("In.00=1234, In.06=180"), so the language shown does not change it; empty where neither
// was read.
QString scopeDriveKind(const DriveDescription &drive);

// A preset found in a folder, and where.
struct ScopePresetEntry
{
    ScopePreset preset;
    QString path;
    bool besidePlant = false;
};

// Where the scope presets live (docs/scope.md, "Presets"): the user's own in the application's
// data folder, and, while a plant is open, those kept beside the plant file
// ("<dir>/<plant base name>.scope-presets"), which come first and are where new ones go: a
// plant's presets travel with its file.
class ScopePresetLibrary
{
    Q_DECLARE_TR_FUNCTIONS(ScopePresetLibrary)
public:
    // `plantFile`: the plant file open in the window; empty: none.
    explicit ScopePresetLibrary(QString plantFile = {});

    static QString userFolder(); // QStandardPaths::AppDataLocation + "/scope-presets"
    static QString plantFolder(const QString &plantFile);
    // The folders listed, beside the plant first.
    QStringList folders() const;
    // Where a preset saved now goes.
    QString saveFolder() const;
    // A file name for the preset's name: the characters no file system takes replaced by '_'.
    static QString fileName(const QString &presetName);

    // The presets for `kind` and those for any drive, beside the plant first, each folder's
    // by name. A file that cannot be read is left out and named in `problems`.
    QList<ScopePresetEntry> list(const QString &kind, QStringList *problems = nullptr) const;
    // Where save() puts a preset of this name; a file there is a preset it would replace.
    QString savePath(const QString &presetName) const;
    // Saves into saveFolder() (made where missing), replacing a preset of the same name there;
    // the file's path in `path`.
    bool save(const ScopePreset &preset, QString *path, QString *error = nullptr) const;

private:
    QString m_plantFile;
};

} // namespace DriveDesk
