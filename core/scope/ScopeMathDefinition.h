#pragma once

#include <QCoreApplication>
#include <QJsonObject>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// A math channel: a trace computed from recorded channels, never sent to a drive. The
// definition is all there is to it (the values follow from the recording), small enough to
// be saved with the recording and to be edited in a dialog.
struct ScopeMathDefinition
{
    Q_DECLARE_TR_FUNCTIONS(ScopeMathDefinition)
public:
    enum class Kind : quint8 {
        Derivative, // d/dt of the source, in its unit per second
        Integral, // of the source over time from its first sample, in its unit times s
        Difference, // the first source minus the second
        Sum, // the first source plus the second
        MovingAverage, // the mean of the samples around each sample
    };
    enum class WindowUnit : quint8 { Samples, Milliseconds };

    Kind kind = Kind::Derivative;
    // The recording's channels it reads (0..3): two for Difference and Sum, one otherwise.
    QList<int> sources { 0 };
    // MovingAverage only: the window's length, in whole samples (at least 1) or ms (more than
    // 0), centred on each sample; at the ends of the trace it holds the samples there are.
    double window = 10;
    WindowUnit windowUnit = WindowUnit::Samples;

    // How many sources a kind reads: 2 for Difference and Sum, else 1.
    static int sourceCount(Kind kind);
    // What is wrong with the definition ("a difference or a sum reads two channels"), empty
    // if nothing. A source must be a channel 0 .. channelCount - 1.
    QString check(int channelCount) const;
    // What is wrong with a moving average's window, empty if nothing (and for other kinds).
    QString checkWindow() const;

    // {"kind": "movingAverage", "sources": [0], "window": 16, "windowUnit": "samples"}; the
    // window's keys only for a moving average. Kinds: derivative, integral, difference, sum,
    // movingAverage; window units: samples, ms.
    QJsonObject toJson() const;
    // The definition of toJson()'s object; nothing, and *error naming the field at fault
    // ("sources: a sum reads two channels", "window: expected a number"), for anything else,
    // an unknown field included.
    static std::optional<ScopeMathDefinition> fromJson(const QJsonObject &json, QString *error);

    bool operator==(const ScopeMathDefinition &) const = default;
};

// The unit of a math channel, derived from its sources' units (DisplayScaling::unitSymbol()):
// a derivative of Hz is Hz/s (of m/s: m/s², of A·s: A), an integral of A is A·s (of m/s: m);
// a difference or sum keeps the unit both sources share, and where they differ it has none
// and says so.
struct ScopeMathUnit
{
    QString symbol; // empty where the sources' units differ
    bool sourcesDiffer = false; // Difference, Sum: the sources' units are not the same
    QString text; // the symbol, or "the units differ: Hz, V" where they do
};

ScopeMathUnit scopeMathUnit(ScopeMathDefinition::Kind kind, const QString &first,
                            const QString &second = {});
// "d/dt ru.03 Actual frequency", "ru.03 Actual frequency − ru.18 Set value", "ru.03 Actual
// frequency, mean of 16 samples": the math channel's title from its sources'.
QString scopeMathTitle(const ScopeMathDefinition &definition, const QString &first,
                       const QString &second = {});

} // namespace DriveDesk
