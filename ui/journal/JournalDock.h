#pragma once

#include "journal/JournalFilter.h"

#include <QDockWidget>
#include <QList>

class QLabel;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;

namespace DriveDesk {

class JournalReader;
class JournalTableModel;
struct JournalReading;

// The journal view (View > Journal): the entries of the journal, newest first, filtered by
// drive, parameter, user and time as `drivedesk-cli journal` filters them (core's
// JournalFilter, the same words), with a search over every field of the entries read. A page
// of the newest entries is read at a time, off the window's thread (JournalReader); Load Older
// reads the page before. Refresh (and the window's writes, through refresh()) reads what came
// since. Revert hands the selected entries on; the filters and columns are remembered.
class JournalDock : public QDockWidget
{
    Q_OBJECT
public:
    static constexpr int kPageSize = 2000;

    // `journalPath` empty: Journal::defaultPath(), the window's.
    explicit JournalDock(QWidget *parent = nullptr, const QString &journalPath = {});
    ~JournalDock() override;

    // Reads what the journal holds since the newest entry shown.
    void refresh();
    // Reads the newest page again, as the filters say.
    void reload();
    // What the drive filter shows when asked for the connected drive ("This Drive").
    void setConnectedDrive(const QString &name);
    void setRevertEnabled(bool enabled);
    void saveSettings() const;

    QTableView *view() const { return m_view; }
    JournalTableModel *model() const { return m_model; }
    QString statusText() const;
    bool isReading() const;
    QList<qint64> selectedEntries() const;

signals:
    void revertRequested(const QList<qint64> &entries);
    void entriesRead(); // a reading is in the table

protected:
    void showEvent(QShowEvent *event) override;

private:
    QLineEdit *addField(const QString &label, const QString &placeholder, const QString &name);
    // The filter the fields say; nothing, and the problem shown, where one cannot be read.
    std::optional<JournalFilter> filter();
    void onRead(const JournalReading &reading);
    void updateStatus();
    void updateButtons();

    JournalReader *m_reader = nullptr;
    JournalTableModel *m_model = nullptr;
    QSortFilterProxyModel *m_proxy = nullptr;
    QTableView *m_view = nullptr;
    QWidget *m_filters = nullptr;
    QLineEdit *m_drive = nullptr;
    QLineEdit *m_parameter = nullptr;
    QLineEdit *m_user = nullptr;
    QLineEdit *m_since = nullptr;
    QLineEdit *m_until = nullptr;
    QLineEdit *m_search = nullptr;
    QPushButton *m_thisDrive = nullptr;
    QPushButton *m_older = nullptr;
    QPushButton *m_revert = nullptr;
    QLabel *m_status = nullptr;
    QString m_connectedDrive;
    QString m_problem; // a filter that cannot be read, or a journal that cannot be
    int m_generation = 0; // readings of earlier filters are dropped
    bool m_loaded = false; // the newest page was read at least once
    bool m_moreOlder = false; // the last page read was full: there may be older entries
    bool m_revertEnabled = false;
};

} // namespace DriveDesk
