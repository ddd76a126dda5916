#pragma once

#include "SampleStore.h"
#include "ScopeFileFormat.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QFile>
#include <QString>

namespace DriveDesk {

// Writes a recording file (.ddscope) while the recording runs: the header at open(), then the
// samples as they come. Samples wait in memory until flush(), or until about 64 KiB are
// pending, and then go to the operating system in one write; a crash of the program loses only
// what was not flushed yet, and leaves a file that reads up to its last complete sample
// (readScopeFile()). Errors name the file and the operating system's reason.
//
// Single-threaded, like the recording it follows.
class ScopeFileWriter
{
    Q_DECLARE_TR_FUNCTIONS(ScopeFileWriter)
public:
    ScopeFileWriter() = default;
    ~ScopeFileWriter(); // flushes and closes; call close() to see an error
    ScopeFileWriter(const ScopeFileWriter &) = delete;
    ScopeFileWriter &operator=(const ScopeFileWriter &) = delete;

    // Creates (or replaces) the file and writes the header. A file whose header could not be
    // written is removed.
    bool open(const QString &path, const ScopeFileHeader &header, QString *error = nullptr);
    bool isOpen() const { return m_file.isOpen(); }
    QString fileName() const { return m_file.fileName(); }

    // Samples in time order, none earlier than the last one appended: a batch that breaks the
    // order is refused whole (false, nothing written), since the reader would refuse the file.
    // False also after a write error, which stays until close().
    bool append(const ScopeSample *samples, qsizetype count, QString *error = nullptr);
    // The samples [begin, end) of a recording's store, e.g. those appended since the last call.
    bool append(const SampleStore &samples, qsizetype begin, qsizetype end,
                QString *error = nullptr);
    // The samples appended so far, flushed or not.
    qsizetype count() const { return m_count; }

    // Hands the pending samples to the operating system.
    bool flush(QString *error = nullptr);
    // Flushes and closes; false if anything failed since open().
    bool close(QString *error = nullptr);

private:
    bool accept(qint64 firstTime, QString *error);
    bool writePending(QString *error);
    QString outOfOrder() const;
    static bool fail(const QString &message, QString *error);

    QFile m_file;
    QByteArray m_pending;
    QString m_error; // the first write error; appends refuse after it
    qint64 m_lastTime = 0;
    qsizetype m_count = 0;
};

} // namespace DriveDesk
