#include "JournalReader.h"

#include "journal/Journal.h"

#include <QFileInfo>
#include <QPromise>
#include <QThreadPool>

namespace DriveDesk {

namespace {

JournalReading readJournal(const QString &path, const JournalFilter &filter, int tag)
{
    JournalReading reading;
    reading.tag = tag;
    Journal journal(path);
    if (!QFileInfo::exists(journal.path()))
        return reading; // nothing written yet: an empty journal
    if (!journal.open(Journal::Access::Read)) {
        reading.error = journal.errorString();
        return reading;
    }
    const std::optional<QList<JournalEntry>> entries = journal.entries(filter);
    if (entries)
        reading.entries = *entries;
    else
        reading.error = journal.errorString();
    return reading;
}

} // namespace

JournalReader::JournalReader(QString path, QObject *parent)
    : QObject(parent)
    , m_path(std::move(path))
{ }

JournalReader::~JournalReader()
{
    // A reading under way ends on its own; its answer goes nowhere.
    for (const auto &watcher : std::as_const(m_waiting))
        watcher->disconnect(this);
}

void JournalReader::read(const JournalFilter &filter, int tag)
{
    auto watcher = std::make_shared<QFutureWatcher<JournalReading>>();
    m_waiting << watcher;
    connect(watcher.get(), &QFutureWatcher<JournalReading>::finished, this, [this] {
        // In order: a reading done early waits for those asked for before it.
        while (!m_waiting.isEmpty() && m_waiting.constFirst()->isFinished()) {
            const auto first = m_waiting.takeFirst();
            emit done(first->result());
        }
    });
    auto promise = std::make_shared<QPromise<JournalReading>>();
    watcher->setFuture(promise->future());
    promise->start();
    QThreadPool::globalInstance()->start([promise, path = m_path, filter, tag] {
        promise->addResult(readJournal(path, filter, tag));
        promise->finish();
    });
}

} // namespace DriveDesk
