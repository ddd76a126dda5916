#pragma once

#include "frame/WindowFeature.h"
#include "journal/JournalEntry.h"

#include <QPointer>

class QAction;
class QTimer;

namespace DriveDesk {

class JournalDock;
class JournalReader;
struct DriveDescription;
struct JournalReading;

// The journal in the window: View > Journal (the JournalDock), each value's last change in the
// table's tooltips (read for the connected drive into its DriveState), and Revert of the
// entries chosen in the view, by core's JournalRevert, handed on as a selection to download
// (revertRequested: the download's checks, last look and report). Reads again a moment after
// the window wrote something.
class JournalFeature : public WindowFeature
{
    Q_OBJECT
public:
    // `journalPath` empty: Journal::defaultPath(), where the window's writes are journaled.
    explicit JournalFeature(WindowFrame &frame, const QString &journalPath = {},
                            QObject *parent = nullptr);

    void attach(DriveSession *session) override;
    void attachFile(const QString &path) override;
    void updateActions() override;
    void saveSettings() override;

    JournalDock *dock() const { return m_dock; }
    // Reverts the entries: refused with a message where JournalRevert refuses them.
    void revert(const QList<qint64> &entries);

signals:
    // What a revert writes (JournalRevertPlan::selection), in words for the last look, and the
    // job its writes are journaled as.
    void revertRequested(const DriveDesk::DriveDescription &selection, const QString &what,
                         const QString &job);
    // The tooltips' last changes were read for the connected drive.
    void changesRead();

private:
    void driveRead();
    void onChangesRead(const JournalReading &reading);
    std::optional<JournalDrive> connectedDrive() const;

    QAction *m_action = nullptr;
    JournalDock *m_dock = nullptr;
    JournalReader *m_changes = nullptr; // the connected drive's entries, for the tooltips
    QTimer *m_written = nullptr; // coalesces the state's changes into one reading
    QPointer<DriveSession> m_session;
    JournalDrive m_drive; // the connected drive as the journal names it, once read
    qint64 m_changesUpTo = 0; // the newest entry the tooltips' changes hold
    int m_changesGeneration = 0;
};

} // namespace DriveDesk
