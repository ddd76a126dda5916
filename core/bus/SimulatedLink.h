#pragma once

#include "link/ConnectionSettings.h"
#include "link/Link.h"

#include <memory>

namespace DriveDesk {

class BusClock;
class SimulatedBus;

// A link to simulated drives in the same thread: no sockets, only timers for latency and
// pacing. Uses settings.protocol and settings.simulation. open() succeeds from the event loop.
class SimulatedLink : public Link
{
    Q_OBJECT
public:
    explicit SimulatedLink(const ConnectionSettings &settings, QObject *parent = nullptr);
    ~SimulatedLink() override;

    void open() override;
    void close() override;
    bool isOpen() const override;
    void send(const QByteArray &bytes) override;
    QString description() const override;

    // The drives behind the link, with their counters (for tests and benchmarks).
    SimulatedBus &bus() { return *m_bus; }

private:
    std::unique_ptr<SimulatedBus> m_bus;
    BusClock *m_clock = nullptr;
    quint64 m_attempt = 0; // a queued opened() of an abandoned open() is not reported
    bool m_open = false;
};

} // namespace DriveDesk
