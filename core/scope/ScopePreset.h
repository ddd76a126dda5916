#pragma once

#include "ScopeSample.h"
#include "ScopeTrigger.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

#include <array>
#include <optional>

namespace DriveDesk {

// A channel's source as a user writes it: a parameter id ("ru.03", "0203h") with the set the
// drive reads it from ("op.11@2"; set 0 without one), or "off".
struct ScopeSourceText
{
    QString id; // empty: off
    int set = 0;

    bool isOff() const { return id.isEmpty(); }
    QString text() const; // "op.11@2", "ru.03", "off"
    // Nothing, and why, where `text` is none of the forms above; the parameter's existence is
    // the drive's to say (session/ScopeAssignment: scopeSourceOn()).
    static std::optional<ScopeSourceText> parse(const QString &text, QString *error = nullptr);
};

// One channel of a preset: what it carries and how it looks.
struct ScopePresetChannel
{
    // Nothing: as the drive has it (nothing is written to that channel).
    std::optional<ScopeSourceText> source;
    QString color; // "#rrggbb"; empty: the channel's default
    bool visible = true;
    bool ownAxis = false; // a value axis of its own

    bool operator==(const ScopePresetChannel &other) const;
};

// A scope set-up saved under a name (docs/scope.md, "Presets"): the four channels' sources and
// looks, the single-shot trigger, the roll length and the rate limit, for one kind of drive.
struct ScopePreset
{
    QString name;
    QString driveKind; // scopeDriveKind() of the drive it was made on; empty: any drive
    std::array<ScopePresetChannel, ScopeSample::kChannelCount> channels{};
    ScopeTriggerSettings trigger;
    double rollSeconds = 10.0;
    int rateLimitHz = 0; // 0: as fast as the link

    bool operator==(const ScopePreset &other) const;
};

// The preset file: JSON, "drivedesk-scope-preset" version 1. Reading checks every field and
// refuses what it does not understand, naming the file and the field.
class ScopePresetFile
{
    Q_DECLARE_TR_FUNCTIONS(ScopePresetFile)
public:
    static constexpr int kVersion = 1;
    static constexpr qint64 kMaxFileSize = 64 * 1024; // a preset is well under 2 KiB
    static constexpr char kSuffix[] = "json";
    static const QString kFormat; // "drivedesk-scope-preset"
    // The ranges the window offers.
    static constexpr double kMinRollSeconds = 0.1;
    static constexpr double kMaxRollSeconds = 3600.0;
    static constexpr int kMaxRateLimitHz = 100000;
    static constexpr qint64 kMinShotMs = 10;
    static constexpr qint64 kMaxShotMs = 3600 * 1000;
    static constexpr double kMaxTriggerLevel = 1e9;

    static QByteArray toJson(const ScopePreset &preset);
    // Nothing, with what is wrong where ("channel 3's source: ..."), for anything that is not
    // a valid preset.
    static std::optional<ScopePreset> fromJson(const QByteArray &json, QString *error = nullptr);

    // Written through QSaveFile: on failure the file at `path` stays as it was.
    static bool save(const QString &path, const ScopePreset &preset, QString *error = nullptr);
    // At most kMaxFileSize bytes are read, and only from a regular file (never /dev/zero or a
    // FIFO). Every error names the file ("preset file 'PATH': channel 3's source: ...").
    static std::optional<ScopePreset> load(const QString &path, QString *error = nullptr);
};

} // namespace DriveDesk
