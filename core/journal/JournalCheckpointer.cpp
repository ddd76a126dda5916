#include "JournalCheckpointer.h"

#include <QAtomicInt>
#include <QSqlDatabase>
#include <QSqlQuery>

namespace DriveDesk {

JournalCheckpointer::JournalCheckpointer(QString path, int busyTimeoutMs)
    : m_path(std::move(path))
    , m_busyTimeoutMs(busyTimeoutMs)
{ }

JournalCheckpointer::~JournalCheckpointer()
{
    {
        const std::lock_guard lock(m_mutex);
        m_stopping = true;
    }
    m_wake.notify_one();
    if (m_thread.joinable())
        m_thread.join();
}

void JournalCheckpointer::request()
{
    {
        const std::lock_guard lock(m_mutex);
        m_requested = true;
        if (!m_thread.joinable())
            m_thread = std::thread([this] { run(); });
    }
    m_wake.notify_one();
}

int JournalCheckpointer::done() const
{
    const std::lock_guard lock(m_mutex);
    return m_done;
}

void JournalCheckpointer::run()
{
    static QAtomicInt counter;
    const QString name
        = QStringLiteral("drivedesk-journal-checkpoint-%1").arg(counter.fetchAndAddRelaxed(1));
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
        db.setDatabaseName(m_path);
        db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=%1").arg(m_busyTimeoutMs));
        const bool opened = db.open();
        std::unique_lock lock(m_mutex);
        for (;;) {
            m_wake.wait(lock, [this] { return m_requested || m_stopping; });
            if (m_stopping)
                break;
            m_requested = false;
            lock.unlock();
            if (opened)
                QSqlQuery(db).exec(QStringLiteral("PRAGMA wal_checkpoint(PASSIVE)"));
            lock.lock();
            ++m_done;
        }
        lock.unlock();
        db.close();
    }
    QSqlDatabase::removeDatabase(name);
}

} // namespace DriveDesk
