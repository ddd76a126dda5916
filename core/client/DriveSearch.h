#pragma once

#include <QList>
#include <QObject>
#include <QPromise>

#include <memory>

namespace DriveDesk {

class ClientWorker;
struct Reply;

// findDrives(): asks one DIN66019II address after the other with a short timeout and no
// retries. Any answer, even a refusal or a garbled one, means a drive is there. HSP5 is point
// to point: one probe of the one drive. Thread: the worker's; deletes itself when done.
class DriveSearch : public QObject
{
    Q_OBJECT
public:
    DriveSearch(ClientWorker &worker, int first, int last, quint16 probeAddress,
                std::shared_ptr<QPromise<QList<int>>> promise);

    void start();
    // Ends the search with the drives found so far; the promise is cancelled already.
    void cancel();

private:
    void probeNext();
    void onProbed(int address, const Reply &reply, bool heard);
    void finish();

    ClientWorker &m_worker;
    const quint64 m_owner;
    QList<int> m_addresses; // still to probe, first to last
    int m_total = 0;
    quint16 m_probeAddress = 0;
    std::shared_ptr<QPromise<QList<int>>> m_promise;
    QList<int> m_found;
    QString m_problem; // why there is nothing to probe
    bool m_finished = false;
};

} // namespace DriveDesk
