#include "ScopePresetLibrary.h"

#include "parameters/DriveIdentity.h"
#include "parameters/ParameterId.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>

namespace DriveDesk {

QString scopeDriveKind(const DriveDescription &drive)
{
    if (!drive.identification.isEmpty())
        return drive.identification;
    const std::optional<DriveKind> kind = DriveIdentity::kind(drive);
    if (!kind)
        return {};
    QStringList values;
    for (const KindValue &value : kind->values)
        values << QStringLiteral("%1=%2").arg(ParameterId::format(value.address, drive)).arg(value.value);
    return values.join(QStringLiteral(", "));
}

ScopePresetLibrary::ScopePresetLibrary(QString plantFile)
    : m_plantFile(std::move(plantFile))
{ }

QString ScopePresetLibrary::userFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
        + QStringLiteral("/scope-presets");
}

QString ScopePresetLibrary::plantFolder(const QString &plantFile)
{
    const QFileInfo plant(plantFile);
    return plant.absoluteDir().filePath(plant.completeBaseName() + QStringLiteral(".scope-presets"));
}

QStringList ScopePresetLibrary::folders() const
{
    QStringList folders;
    if (!m_plantFile.isEmpty())
        folders << plantFolder(m_plantFile);
    folders << userFolder();
    return folders;
}

QString ScopePresetLibrary::saveFolder() const
{
    return folders().constFirst();
}

QString ScopePresetLibrary::fileName(const QString &presetName)
{
    QString name = presetName.trimmed();
    for (QChar &c : name) {
        if (c.unicode() < 0x20 || QStringLiteral("/\\:*?\"<>|").contains(c))
            c = QLatin1Char('_');
    }
    // A leading dot would hide the file; the name itself stays in the file.
    if (name.startsWith(QLatin1Char('.')))
        name[0] = QLatin1Char('_');
    return name + QLatin1Char('.') + QLatin1String(ScopePresetFile::kSuffix);
}

QList<ScopePresetEntry> ScopePresetLibrary::list(const QString &kind, QStringList *problems) const
{
    QList<ScopePresetEntry> entries;
    const QStringList searched = folders();
    for (const QString &folder : searched) {
        const QFileInfoList files = QDir(folder).entryInfoList(
            {QStringLiteral("*.") + QLatin1String(ScopePresetFile::kSuffix)}, QDir::Files,
            QDir::Name);
        QList<ScopePresetEntry> found;
        for (const QFileInfo &file : files) {
            QString error;
            std::optional<ScopePreset> preset = ScopePresetFile::load(file.filePath(), &error);
            if (!preset) {
                if (problems)
                    *problems << error;
                continue;
            }
            if (!preset->driveKind.isEmpty() && preset->driveKind != kind)
                continue;
            found.append({std::move(*preset), file.filePath(),
                          !m_plantFile.isEmpty() && folder == searched.constFirst()});
        }
        std::stable_sort(found.begin(), found.end(),
                         [](const ScopePresetEntry &a, const ScopePresetEntry &b) {
                             return a.preset.name.localeAwareCompare(b.preset.name) < 0;
                         });
        entries << found;
    }
    return entries;
}

QString ScopePresetLibrary::savePath(const QString &presetName) const
{
    return QDir(saveFolder()).filePath(fileName(presetName));
}

bool ScopePresetLibrary::save(const ScopePreset &preset, QString *path, QString *error) const
{
    const QString folder = saveFolder();
    if (!QDir().mkpath(folder)) {
        if (error)
            *error = tr("cannot make the folder '%1' for the presets").arg(folder);
        return false;
    }
    const QString file = savePath(preset.name);
    if (path)
        *path = file;
    return ScopePresetFile::save(file, preset, error);
}

} // namespace DriveDesk
