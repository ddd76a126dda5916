#pragma once

#include <QDateTime>
#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace DriveDesk {

// Which entries of the journal to show (`drivedesk-cli journal`, docs/journal.md): each part
// that is set narrows them, one left unset does not. The setters take the words a user types,
// check them and keep what the query matches; false and *error (naming the text) for words
// that make no sense.
class JournalFilter
{
public:
    // A drive: the link as it was given ("serial:/dev/ttyUSB0", "tcp:10.0.0.5:5020", "sim":
    // every drive on it; a link has a ':' or is "sim"), "LINK@ADDRESS" for the drive at that
    // bus address ("serial:/dev/ttyUSB0@3"), or else its serial number.
    bool setDrive(const QString &text, QString *error);
    // "op.28", "op.028", "OP.28" (the group matched case-insensitively, the number by value),
    // or an address "0x0A1C", "0A1Ch".
    bool setParameter(const QString &text, QString *error);
    // "2026-11-24", "2026-11-24T10:42", "2026-11-24 10:42:30", local time unless followed by
    // Z or an offset like +01:00. Each names a span (a day, a minute, a second): since takes
    // the span's start, until its end, so --until 2026-11-24 includes that day.
    bool setSince(const QString &text, QString *error);
    bool setUntil(const QString &text, QString *error);
    void setUser(const QString &login) { m_user = login; }
    // Only these entries, by id (a revert names them); empty: any.
    void setEntries(const QList<qint64> &ids) { m_entries = ids; }
    // Only entries begun after this one: what a view that has read up to it lacks.
    void setAfterEntry(qint64 id) { m_afterEntry = id; }
    // Only entries begun before this one: the page before those a view shows.
    void setBeforeEntry(qint64 id) { m_beforeEntry = id; }
    // Only the newest `count` entries that match (0: all): a page of a big journal.
    void setNewest(int count) { m_newest = count; }

    // The moment a span of time text begins (end = false) or the moment after it ends (true).
    static std::optional<QDateTime> parseTime(const QString &text, bool end, QString *error);

    // What the query matches (empty or unset: anything).
    const QString &serialNumber() const { return m_serialNumber; }
    const QString &link() const { return m_link; } // without the address
    const std::optional<int> &driveAddress() const { return m_address; } // with LINK@ADDRESS
    const std::optional<quint16> &parameterAddress() const { return m_parameterAddress; }
    const QStringList &parameterIds() const { return m_parameterIds; } // "op.28", "op.028"
    const QDateTime &since() const { return m_since; } // UTC, inclusive
    const QDateTime &until() const { return m_until; } // UTC, exclusive
    const QString &user() const { return m_user; }
    const QList<qint64> &entries() const { return m_entries; }
    qint64 afterEntry() const { return m_afterEntry; }
    qint64 beforeEntry() const { return m_beforeEntry; }
    int newest() const { return m_newest; }

private:
    QString m_serialNumber;
    QString m_link;
    std::optional<int> m_address;
    std::optional<quint16> m_parameterAddress;
    QStringList m_parameterIds;
    QDateTime m_since;
    QDateTime m_until;
    QString m_user;
    QList<qint64> m_entries;
    qint64 m_afterEntry = 0;
    qint64 m_beforeEntry = 0;
    int m_newest = 0;
};

} // namespace DriveDesk
