#pragma once

#include "client/DriveClient.h"

#include <QFutureWatcher>
#include <QObject>

#include <optional>

namespace DriveDesk {

class DriveState;

// One connection to one drive and the way from connecting over the scan to a filled state:
// the client (working in its own thread), which the features' controllers (edits, polling, the
// password level) work through; they follow the session's signals. A lost link leaves the state
// as it is; reconnecting re-reads the values, or the whole drive where the state holds it only in
// part. A scan that stops early never replaces a complete description: the state keeps the
// metadata and values read before.
// Lives in the GUI thread.
class DriveSession : public QObject
{
    Q_OBJECT
public:
    DriveSession(const ConnectionSettings &settings, DriveState *state,
                 QObject *parent = nullptr);
    ~DriveSession() override;

    DriveClient *client() const { return m_client; }
    const ConnectionSettings &settings() const { return m_client->settings(); }
    DriveClient::State state() const { return m_client->state(); }
    // Connected, but the drive does not answer (DriveClient::isDriveSilent()).
    bool isDriveSilent() const { return m_client->isDriveSilent(); }

    // Connects; the first time the drive is scanned into the state, later its values re-read
    // (the whole drive again while the state holds it only in part).
    void start();
    // Closes the link where it is open, waits until it is closed, and connects again.
    void reconnect();
    void disconnectFromDrive();
    void cancelScan();
    // Reads the drive into the state: metadata from the cache where the drive is of a cached
    // kind, or from the drive (RefreshCache: "Read metadata again").
    void rescan(MetadataSource metadata = MetadataSource::Cache);
    bool isScanning() const { return m_scan.isRunning(); }
    // A scan filled the state: there is something to edit and to refresh.
    bool hasDescription() const { return m_described; }
    // Why the description in the state is incomplete (the scan that filled it stopped early or
    // missed something); empty when it is complete or there is none.
    QString incompleteReason() const { return m_incompleteReason; }

    // Connected, the state holds the drive, and no scan runs: values may be read and written.
    bool isReady() const;
    // Refresh: the values shown are read again (valuesRequested()); the whole drive where the
    // state does not hold it yet.
    void readValuesAgain();

    // Fr.02 (active set) and Fr.09 (set pointer) where the drive has them.
    std::optional<quint16> activeSetAddress() const { return m_activeSet; }
    std::optional<quint16> setPointerAddress() const { return m_setPointer; }
    // Fr.02 as last read; -1 when unknown.
    int activeSet() const;

signals:
    // The link's own signals (its state, a failed connection, a lost link, a silent drive) come
    // from client(); these say what the session makes of them.
    // Connected: the drive is read next (scanned, or its values read again).
    void connected();
    void scanStarted();
    void scanProgress(int value, int maximum, const QString &text);
    // The state holds the drive now. `drive` is the scan's result (metadata and values).
    void described(const DriveDesk::DriveDescription &drive);
    // Empty when the scan read everything; otherwise why it stopped or what it missed.
    void scanFinished(const QString &problem);
    // A re-read stopped early (`reason`): what it read is dropped, the state keeps the complete
    // description it held. Comes instead of described() and scanFinished().
    void scanDiscarded(const QString &reason);
    // Connected and the state holds the drive, after a scan or back after a lost link: what
    // goes with a drive read (its password level, polling) starts now.
    void ready();
    // The values shown are to be read from the drive again (Refresh, back after a lost link,
    // after a download).
    void valuesRequested();
    // The drive holds none of what was written to it (the built-in simulated drive, made anew
    // on every connection): the written marks and the undo history go.
    void writesLost();
    // The link is about to close: what runs on its own (polling) stops now.
    void closing();

private:
    void onConnected();
    void onScanFinished();
    void readSetPointers();

    DriveClient *m_client = nullptr; // owned; the features drop their controllers before it goes
    DriveState *m_state = nullptr;
    QFutureWatcher<DriveDescription> m_scan;
    std::optional<quint16> m_activeSet;
    std::optional<quint16> m_setPointer;
    bool m_described = false;
    QString m_incompleteReason; // of the description in the state
    bool m_reconnecting = false; // reconnect(): connect once the old link is closed
};

} // namespace DriveDesk
