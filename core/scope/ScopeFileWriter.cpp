#include "ScopeFileWriter.h"

#include <QFileInfo>

namespace DriveDesk {

namespace {

// Pending samples are written once this much has come together: at 1 kHz every few seconds,
// a few system calls a minute, and little to lose in a crash even without flush().
constexpr qsizetype kPendingLimit = 64 * 1024;

} // namespace

ScopeFileWriter::~ScopeFileWriter()
{
    if (isOpen())
        close();
}

bool ScopeFileWriter::open(const QString &path, const ScopeFileHeader &header, QString *error)
{
    if (isOpen())
        close();
    m_pending.clear();
    m_error.clear();
    m_lastTime = 0;
    m_count = 0;
    m_file.setFileName(path);
    // Unbuffered: this class gathers the samples itself, and flush() is to reach the file.
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered)) {
        if (error)
            *error = tr("cannot write '%1': %2").arg(path, m_file.errorString());
        return false;
    }
    const QByteArray start = ScopeFileFormat::start(header);
    if (m_file.write(start) != start.size()) {
        const QString message = tr("cannot write '%1': %2").arg(path, m_file.errorString());
        m_file.close();
        if (QFileInfo(path).isFile()) // never a device such as /dev/full
            m_file.remove();
        if (error)
            *error = message;
        return false;
    }
    return true;
}

bool ScopeFileWriter::append(const ScopeSample *samples, qsizetype count, QString *error)
{
    if (!accept(count > 0 ? samples[0].time : m_lastTime, error))
        return false;
    for (qsizetype i = 1; i < count; ++i) {
        if (samples[i].time < samples[i - 1].time)
            return fail(outOfOrder(), error);
    }
    const qsizetype at = m_pending.size();
    m_pending.resize(at + count * ScopeFileFormat::kRecordSize);
    char *to = m_pending.data() + at;
    for (qsizetype i = 0; i < count; ++i, to += ScopeFileFormat::kRecordSize)
        ScopeFileFormat::encode(samples[i], to);
    if (count > 0) {
        m_count += count;
        m_lastTime = samples[count - 1].time;
    }
    return m_pending.size() < kPendingLimit || writePending(error);
}

bool ScopeFileWriter::append(const SampleStore &samples, qsizetype begin, qsizetype end,
                             QString *error)
{
    Q_ASSERT(begin >= 0 && begin <= end && end <= samples.count());
    // The store keeps its samples in order; only the first can be out of step with the file.
    if (!accept(begin < end ? samples.time(begin) : m_lastTime, error))
        return false;
    const qsizetype at = m_pending.size();
    m_pending.resize(at + (end - begin) * ScopeFileFormat::kRecordSize);
    char *to = m_pending.data() + at;
    for (qsizetype i = begin; i < end; ++i, to += ScopeFileFormat::kRecordSize)
        ScopeFileFormat::encode(samples.at(i), to);
    if (begin < end) {
        m_count += end - begin;
        m_lastTime = samples.time(end - 1);
    }
    return m_pending.size() < kPendingLimit || writePending(error);
}

bool ScopeFileWriter::flush(QString *error)
{
    return accept(m_lastTime, error) && writePending(error);
}

bool ScopeFileWriter::close(QString *error)
{
    if (!isOpen())
        return true;
    const bool flushed = flush(error);
    m_file.close();
    const bool closed = m_file.error() == QFileDevice::NoError;
    if (flushed && !closed && error)
        *error = tr("cannot write '%1': %2").arg(m_file.fileName(), m_file.errorString());
    m_pending.clear();
    m_error.clear();
    return flushed && closed;
}

// Whether samples from `firstTime` on may be written now; the reason where not.
bool ScopeFileWriter::accept(qint64 firstTime, QString *error)
{
    if (!isOpen())
        return fail(tr("no recording file is open"), error);
    if (!m_error.isEmpty())
        return fail(m_error, error);
    if (m_count > 0 && firstTime < m_lastTime)
        return fail(outOfOrder(), error);
    return true;
}

QString ScopeFileWriter::outOfOrder() const
{
    return tr("cannot write '%1': a sample is earlier than the one before it")
        .arg(m_file.fileName());
}

bool ScopeFileWriter::writePending(QString *error)
{
    if (m_pending.isEmpty())
        return true;
    if (m_file.write(m_pending) != m_pending.size()) {
        // Part of it may be in the file: the reader leaves out an incomplete last sample.
        m_error = tr("cannot write '%1': %2").arg(m_file.fileName(), m_file.errorString());
        return fail(m_error, error);
    }
    m_pending.resize(0); // keeps the capacity for the next samples
    return true;
}

bool ScopeFileWriter::fail(const QString &message, QString *error)
{
    if (error)
        *error = message;
    return false;
}

} // namespace DriveDesk
