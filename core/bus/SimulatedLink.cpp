#include "SimulatedLink.h"

#include "BusClock.h"
#include "SimulatedBus.h"

#include <QStringList>

namespace DriveDesk {

SimulatedLink::SimulatedLink(const ConnectionSettings &settings, QObject *parent)
    : Link(parent)
    , m_bus(std::make_unique<SimulatedBus>(settings.protocol, settings.simulation))
    , m_clock(new BusClock(m_bus.get(), this))
{
    connect(m_clock, &BusClock::transmit, this, &SimulatedLink::handOnWithLineErrors);
}

SimulatedLink::~SimulatedLink()
{
    // The clock refers to the bus: it goes first.
    delete m_clock;
}

void SimulatedLink::openTransport()
{
    reportOutcomeLater();
}

void SimulatedLink::closeTransport()
{
    m_clock->resetLine();
}

void SimulatedLink::transmit(const QByteArray &bytes)
{
    m_clock->receive(bytes);
}

// lineErrors: the indices before which the line flagged a character.
void SimulatedLink::handOnWithLineErrors(const QByteArray &bytes,
                                         const QList<qsizetype> &lineErrors)
{
    qsizetype from = 0;
    for (qsizetype at : lineErrors) {
        if (at > from)
            handOn(bytes.mid(from, at - from));
        from = at;
        handOnLineError(tr("parity error on a received character"));
    }
    handOn(bytes.mid(from));
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
