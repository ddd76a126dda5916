#include "ScopeFileReader.h"

#include "ScopeFileFormat.h"
#include "ScopeRecording.h"
#include "parameters/WholeFile.h"

#include <QCoreApplication>
#include <QFile>
#include <QtEndian>

#include <algorithm>
#include <cstring>

namespace DriveDesk {

namespace {

// Samples are read in blocks of this many records (1.3 MB): a million samples in 16 reads.
constexpr qsizetype kBlockRecords = 65536;
// Room for the magic line of any version.
constexpr qint64 kMagicLineMax = 32;

bool fail(QString *error, const QString &message)
{
    if (error)
        *error = message;
    return false;
}

QString unreadable(const QFile &file)
{
    return QCoreApplication::translate("ScopeFile", "cannot read '%1': %2")
        .arg(file.fileName(), file.errorString());
}

QString damaged(const QString &path, const QString &why)
{
    return QCoreApplication::translate("ScopeFile", "'%1' is damaged: %2").arg(path, why);
}

// The format version on the magic line, and where the line ends; version 0 if `head` (the
// file's first bytes) does not start with one.
std::pair<int, qsizetype> magicLine(const QByteArray &head)
{
    const QByteArray magic(ScopeFileFormat::kMagic);
    if (!head.startsWith(magic))
        return { 0, 0 };
    const qsizetype end = head.indexOf('\n', magic.size());
    const QByteArray digits = head.mid(magic.size(), end - magic.size());
    if (end < 0 || digits.isEmpty() || digits.size() > 6
        || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return { 0, 0 };
    return { digits.toInt(), end + 1 };
}

// The magic line and the header; false with the message where they are not a readable start.
bool readStart(QFile &file, ScopeFileHeader &header, QString *error)
{
    const QString path = file.fileName();
    const QByteArray head = file.read(kMagicLineMax);
    if (head.isEmpty() && file.error() != QFileDevice::NoError)
        return fail(error, unreadable(file));
    const auto [version, headerAt] = magicLine(head);
    if (version < 1)
        return fail(error,
                    QCoreApplication::translate("ScopeFile", "'%1' is not a DriveDesk scope file")
                        .arg(path));
    if (version > ScopeFileFormat::kVersion)
        return fail(
            error,
            QCoreApplication::translate("ScopeFile",
                                        "'%1' is in scope file format %2 of a newer DriveDesk; "
                                        "this version reads format %3")
                .arg(path)
                .arg(version)
                .arg(ScopeFileFormat::kVersion));
    if (!file.seek(headerAt))
        return fail(error, unreadable(file));

    const QByteArray length = file.read(4);
    const quint32 size = length.size() == 4 ? qFromLittleEndian<quint32>(length.constData()) : 0;
    if (size > ScopeFileFormat::kMaxHeaderSize)
        return fail(
            error,
            damaged(path,
                    QCoreApplication::translate("ScopeFile", "its header cannot be %1 bytes long")
                        .arg(size)));
    const QByteArray json = length.size() == 4 ? file.read(size) : QByteArray();
    if (file.error() != QFileDevice::NoError)
        return fail(error, unreadable(file));
    if (length.size() != 4 || json.size() != qsizetype(size))
        return fail(
            error,
            damaged(path, QCoreApplication::translate("ScopeFile", "its header is cut short")));
    QString fault;
    if (!ScopeFileFormat::parseHeader(json, header, &fault))
        return fail(error,
                    QCoreApplication::translate("ScopeFile", "'%1' has a damaged header: %2")
                        .arg(path, fault));
    return true;
}

// The records after the header into `recording`; the bytes of an incomplete last record are
// left over in `incomplete`.
bool readSamples(QFile &file, ScopeRecording &recording, qsizetype &incomplete, QString *error)
{
    constexpr qsizetype kRecord = ScopeFileFormat::kRecordSize;
    QByteArray block(kBlockRecords * kRecord, Qt::Uninitialized);
    qsizetype carried = 0;
    for (;;) {
        const qint64 got = file.read(block.data() + carried, block.size() - carried);
        if (got < 0)
            return fail(error, unreadable(file));
        if (got == 0)
            break;
        const qsizetype available = carried + got;
        const qsizetype complete = available - available % kRecord;
        for (qsizetype at = 0; at < complete; at += kRecord) {
            if (!recording.buffer.append(ScopeFileFormat::decode(block.constData() + at)))
                return fail(error,
                            damaged(file.fileName(),
                                    QCoreApplication::translate(
                                        "ScopeFile", "sample %1 is earlier than the one before it")
                                        .arg(recording.buffer.count() + 1)));
        }
        carried = available - complete;
        std::memmove(block.data(), block.constData() + complete, size_t(carried));
    }
    incomplete = carried;
    return true;
}

} // namespace

bool readScopeFile(const QString &path, ScopeRecording &out, QString *error, QStringList *warnings)
{
    if (const QString refused = WholeFile::refusal(path); !refused.isEmpty())
        return fail(error, refused);
    QFile file(path);
    // Unbuffered: the blocks are large, a second copy through QFile's buffer would only cost.
    if (!file.open(QIODevice::ReadOnly | QIODevice::Unbuffered))
        return fail(error, unreadable(file));
    ScopeFileHeader header;
    if (!readStart(file, header, error))
        return false;
    ScopeRecording loaded;
    loaded.started = header.started;
    loaded.source = header.source;
    loaded.channels = header.channels;
    loaded.math = header.math;
    loaded.triggerMs = header.triggerMs;
    qsizetype incomplete = 0;
    if (!readSamples(file, loaded, incomplete, error))
        return false;
    if (incomplete > 0 && warnings)
        warnings->append(QCoreApplication::translate(
                             "ScopeFile",
                             "'%1' ends in an incomplete sample (%n byte(s)), which was left out: "
                             "the recording was cut off",
                             nullptr, int(incomplete))
                             .arg(path));
    out = std::move(loaded);
    return true;
}

} // namespace DriveDesk
