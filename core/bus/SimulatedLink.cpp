#include "SimulatedLink.h"

#include "BusClock.h"
#include "SimulatedBus.h"

#include <QStringList>
#include <QTimer>

namespace DriveDesk {

SimulatedLink::SimulatedLink(const ConnectionSettings &settings, QObject *parent)
    : Link(parent)
    , m_bus(std::make_unique<SimulatedBus>(settings.protocol, settings.simulation))
    , m_clock(new BusClock(m_bus.get(), this))
{
    connect(m_clock, &BusClock::transmit, this,
            [this](const QByteArray &bytes, const QList<qsizetype> &lineErrors) {
                qsizetype from = 0;
                for (qsizetype at : lineErrors) {
                    if (!m_open)
                        return;
                    if (at > from)
                        emit received(bytes.mid(from, at - from));
                    from = at;
                    if (m_open)
                        emit lineError(tr("parity error on a received character"));
                }
                if (m_open && from < bytes.size())
                    emit received(bytes.mid(from));
            });
}

SimulatedLink::~SimulatedLink()
{
    // The clock refers to the bus: it goes first.
    delete m_clock;
}

void SimulatedLink::open()
{
    close();
    const quint64 attempt = ++m_attempt;
    QTimer::singleShot(0, this, [this, attempt] {
        if (attempt != m_attempt)
            return;
        m_open = true;
        emit opened();
    });
}

void SimulatedLink::close()
{
    ++m_attempt;
    m_open = false;
    m_clock->resetLine();
}

bool SimulatedLink::isOpen() const
{
    return m_open;
}

void SimulatedLink::send(const QByteArray &bytes)
{
    if (!m_open) {
        qWarning("DriveDesk: %d bytes not sent: %s is not open", int(bytes.size()),
                 qPrintable(description()));
        return;
    }
    m_clock->receive(bytes);
}

QString SimulatedLink::description() const
{
    const SimulationOptions &options = m_bus->options();
    if (m_bus->protocol() == Protocol::Hsp5)
        return tr("simulated drive");
    QStringList addresses;
    for (int address : options.driveAddresses)
        addresses.append(QString::number(address));
    const int count = int(addresses.size());
    return tr("simulated drive(s) %1", nullptr, count).arg(addresses.join(QStringLiteral(", ")));
}

} // namespace DriveDesk
