#pragma once

#include "journal/JournalEntry.h"
#include "journal/JournalFilter.h"

#include <QFutureWatcher>
#include <QList>
#include <QObject>

#include <memory>

namespace DriveDesk {

// What one reading of the journal brought: the entries (oldest first), or why there are none.
struct JournalReading
{
    int tag = 0; // the caller's: which reading this answers
    QList<JournalEntry> entries;
    QString error;
};

// Reads the journal off the window's thread: each read() opens the journal in a thread of the
// pool (a Journal belongs to the thread that opens it), reads what the filter lets through and
// closes it again, so a journal of 100,000 entries never stalls the window. The readings come
// back through done(), in the window's thread, in the order they were asked for.
class JournalReader : public QObject
{
    Q_OBJECT
public:
    explicit JournalReader(QString path = {}, QObject *parent = nullptr);
    ~JournalReader() override;

    const QString &path() const { return m_path; }
    void read(const JournalFilter &filter, int tag);
    bool isReading() const { return !m_waiting.isEmpty(); }

signals:
    void done(const DriveDesk::JournalReading &reading);

private:
    QString m_path;
    QList<std::shared_ptr<QFutureWatcher<JournalReading>>> m_waiting;
};

} // namespace DriveDesk
