#pragma once

#include "link/ConnectionSettings.h"

#include <QByteArray>
#include <QList>
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
    enum class Fate : quint8 {
        Passed,
        Lost,        // gone without a trace
        ParityError, // one bit flipped: the receiving UART flags it and discards the character
        Flipped,     // one bit flipped, unflagged: the character arrives changed
    };
    // One character on the line.
    Fate pass(char *byte);
    // A stretch of characters on the line: what got through, and where (*lineErrors, may be
    // null) the receiver was told of a flagged character: before that index of the result.
    QByteArray pass(const QByteArray &bytes, QList<qsizetype> *lineErrors);

private:
    double m_corruptRate = 0;
    double m_dropRate = 0;
    double m_flipRate = 0;
    int m_dataBits = 8;
    BusCounters *m_counters = nullptr;
    QRandomGenerator m_random;
};

} // namespace DriveDesk
