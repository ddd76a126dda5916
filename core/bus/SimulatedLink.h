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

    QString description() const override;

    // The drives behind the link, with their counters (for tests and benchmarks).
    SimulatedBus &bus() { return *m_bus; }

private:
    void openTransport() override;
    void closeTransport() override;
    void transmit(const QByteArray &bytes) override;
    void handOnWithLineErrors(const QByteArray &bytes, const QList<qsizetype> &lineErrors);

    std::unique_ptr<SimulatedBus> m_bus;
    BusClock *m_clock = nullptr;
};

} // namespace DriveDesk
