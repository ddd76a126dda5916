#pragma once

#include <QString>

#include <condition_variable>
#include <mutex>
#include <thread>

namespace DriveDesk {

// Copies a journal's write-ahead log into its file (SQLite's passive checkpoint) in a thread
// of its own, with a connection of its own, so that the disk syncs a checkpoint takes (tens of
// milliseconds on a slow disk) never hold up an entry. The thread starts at the first request.
// A checkpoint that fails loses nothing (the log keeps the entries) and is left to the next.
class JournalCheckpointer
{
public:
    JournalCheckpointer(QString path, int busyTimeoutMs);
    // Waits for a checkpoint under way, then stops the thread.
    ~JournalCheckpointer();
    JournalCheckpointer(const JournalCheckpointer &) = delete;
    JournalCheckpointer &operator=(const JournalCheckpointer &) = delete;

    // A checkpoint soon; returns at once. Requests while one runs make one more.
    void request();
    // Checkpoints done so far (for tests and the benchmark).
    int done() const;

private:
    void run();

    const QString m_path;
    const int m_busyTimeoutMs;
    std::thread m_thread;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_requested = false;
    bool m_stopping = false;
    int m_done = 0;
};

} // namespace DriveDesk
