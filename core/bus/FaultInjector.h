#pragma once

#include "link/ConnectionSettings.h"

#include <QByteArray>
#include <QRandomGenerator>

namespace DriveDesk {

struct BusCounters;

// The faults SimulationOptions asks for, drawn from a generator seeded with options.seed: the
// same seed and traffic give the same faults. Counts what it injects into *counters.
class FaultInjector
{
public:
    FaultInjector(const SimulationOptions &options, int dataBits, BusCounters *counters);

    // True with the given chance; a rate of 0 draws nothing.
    bool draw(double rate);
    // One character on the line: false if it is lost, else maybe with one data bit flipped.
    bool pass(char *byte);
    // A stretch of characters on the line, with what got through.
    QByteArray pass(const QByteArray &bytes);

private:
    double m_corruptRate = 0;
    double m_dropRate = 0;
    int m_dataBits = 8;
    BusCounters *m_counters = nullptr;
    QRandomGenerator m_random;
};

} // namespace DriveDesk
