#pragma once

#include "ScopeChannel.h"
#include "ScopeMathDefinition.h"
#include "ScopeSample.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QDateTime>
#include <QString>

#include <optional>

namespace DriveDesk {

struct ScopeRecording;

// What a recording file holds besides its samples.
struct ScopeFileHeader
{
    QDateTime started; // UTC, may be invalid (not known when the file was opened)
    QString source;
    ScopeChannels channels = ScopeChannels(ScopeSample::kChannelCount);
    QList<ScopeMathDefinition> math; // "math" in the file; absent where there are none
    std::optional<qint64> triggerMs; // "trigger" in the file; absent for a recording no shot

    static ScopeFileHeader of(const ScopeRecording &recording);
};

// The layout of a recording file (.ddscope), shared by ScopeFileWriter and readScopeFile():
// a magic line with the format version, the header's length and the header as JSON, then one
// fixed-size little-endian record per sample (docs/scope.md, "The recording file").
class ScopeFileFormat
{
    Q_DECLARE_TR_FUNCTIONS(ScopeFileFormat)
public:
    static constexpr int kVersion = 1;
    // The first bytes of every version; the version in decimal and '\n' follow.
    static constexpr char kMagic[] = "DriveDesk scope ";
    static constexpr char kSuffix[] = "ddscope";
    // time (int64), the wide channels (2 x int32), the narrow ones (2 x int16)
    static constexpr qsizetype kRecordSize = 20;
    // A header is a few hundred bytes; a length above this means the file is damaged.
    static constexpr quint32 kMaxHeaderSize = 1 << 20;

    // The magic line, the header's length (uint32 little-endian) and the header.
    static QByteArray start(const ScopeFileHeader &header);
    // The header from its JSON. False with the fault and where it is ("channels[2].scaling
    // .divisor: expected an integer"); `header` is then partly filled.
    static bool parseHeader(const QByteArray &json, ScopeFileHeader &header, QString *error);

    static void encode(const ScopeSample &sample, char *to);
    static ScopeSample decode(const char *from);
};

} // namespace DriveDesk
