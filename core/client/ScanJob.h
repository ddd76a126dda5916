#pragma once

#include "client/DriveClient.h"
#include "client/RequestJob.h"

#include <QPointer>

#include <functional>
#include <memory>

namespace DriveDesk {

class DriveScanner;

// A drive scan (DriveScanner) as the client runs every job of many requests: on the client's
// queue in its thread, reporting through its future (progress 0..1000, the description as
// its one result). Cancelling the future drops the result; finishEarly() ends the scan with
// what it read (incompleteReason "cancelled").
class ScanJob : public RequestJob<DriveDescription>
{
public:
    // `connection` names the link as the description records it; asked when the scan ends,
    // in the client's thread. `owner` lives in the client's thread and outlives every job there:
    // the scanner is its child, so a client closed mid-scan leaves nothing behind.
    ScanJob(ScanOptions options, const ConnectionSettings &settings,
            std::function<QString()> connection, QObject *owner);
    ~ScanJob() override;

    void finishEarly() override;

protected:
    void start() override;
    void stopping() override;

private:
    void onFinished(const DriveDescription &found);

    ScanOptions m_options;
    ConnectionSettings m_settings;
    std::function<QString()> m_connection;
    QObject *m_owner = nullptr;
    QPointer<DriveScanner> m_scanner; // until it finished
    int m_shownProgress = 0;
};

} // namespace DriveDesk
