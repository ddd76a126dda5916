#pragma once

#include "journal/JournalEntry.h"
#include "journal/JournalFilter.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

class QSqlQuery;

namespace DriveDesk {

class JournalCheckpointer;

// The journal of every value DriveDesk writes (docs/journal.md): an SQLite file through Qt SQL,
// in write-ahead-log mode, that the window and any number of command lines write at once. An
// entry is begun (outcome unknown) before its telegram is sent and completed when the answer
// comes, so a program that dies leaves it unknown, never missing. Each call is one short
// transaction; another program's transaction is waited for up to the busy timeout.
//
// Each Journal has its own database connection, to be used from one thread: the one that
// opened it. A call that fails returns false or nothing and leaves its reason, naming the file,
// in errorString(): a write whose entry cannot be begun must not be sent.
class Journal
{
    Q_DECLARE_TR_FUNCTIONS(Journal)
public:
    enum class Access : quint8 { Write, Read };
    static constexpr int kDefaultBusyTimeoutMs = 5000;
    // Entries completed after which the log is copied into the file, beside the entries.
    static constexpr int kCheckpointEntries = 500;

    // $XDG_DATA_HOME/DriveDesk/journal.sqlite (~/.local/share/...), the window's and the
    // command line's alike; another for this program's run after setDefaultPath().
    static QString defaultPath();
    // `drivedesk --journal PATH`: every part of the window that journals or reads the journal
    // uses PATH. Set once at start, before any other thread runs; empty: the standard place.
    static void setDefaultPath(const QString &path);

    // `path` empty: defaultPath(). Nothing is opened yet.
    explicit Journal(QString path = {});
    ~Journal();
    Journal(const Journal &) = delete;
    Journal &operator=(const Journal &) = delete;

    const QString &path() const { return m_path; }
    // How long a call waits for another program's transaction before it fails as locked.
    // Takes effect at the next open().
    void setBusyTimeout(int ms) { m_busyTimeoutMs = ms; }
    int busyTimeout() const { return m_busyTimeoutMs; }

    // Write: makes the folder and the file where missing and checks that an entry could be
    // written now (not read-only, not locked past the timeout, not full, a journal of this or
    // an older version). Read: the file must exist and be a journal. False and errorString()
    // otherwise.
    bool open(Access access = Access::Write);
    void close();
    bool isOpen() const { return m_statements != nullptr; }
    QString errorString() const { return m_error; }

    // A job the entries that follow belong to: "edit", "download of f5.json". Its id for
    // JournalEntry::jobId, or nothing.
    std::optional<qint64> beginJob(const QString &description);
    // Stores the entry as unknown, before its telegram is sent; its id, or nothing. Where the
    // entry leaves them empty, the time is now and the user, host and program are this
    // process's. The values of a password entry are never stored.
    std::optional<qint64> begin(const JournalEntry &entry);
    // What became of the entry: the value read back, the outcome, and the drive's reason for a
    // refusal (or why it is unknown). False for an entry the journal does not have.
    bool complete(qint64 id, const JournalValue &readBack, JournalOutcome outcome,
                  const QString &reason = {});

    // Runs `work` as one transaction: the entries it begins and completes are stored together,
    // or not at all where it returns false; one commit for many entries instead of one each.
    // A call inside `work` joins the transaction. False, with errorString(), when it failed.
    bool transaction(const std::function<bool()> &work);

    // The entries the filter lets through, in the order they were begun (newest last), or
    // nothing when the journal cannot be read.
    std::optional<QList<JournalEntry>> entries(const JournalFilter &filter = {});

private:
    struct Statements;

    bool fail(const QString &message);
    bool prepare(Access access);
    bool switchToLog(QSqlQuery &query) const;

    QString m_path;
    QString m_connection; // the QSqlDatabase connection's unique name
    int m_busyTimeoutMs = kDefaultBusyTimeoutMs;
    Access m_access = Access::Write;
    int m_entriesSinceCheckpoint = 0;
    bool m_inTransaction = false;
    std::unique_ptr<Statements> m_statements; // set while open
    std::unique_ptr<JournalCheckpointer> m_checkpointer; // from the first checkpoint on
    QString m_error;
};

} // namespace DriveDesk
