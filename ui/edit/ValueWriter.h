#pragma once

#include "parameters/DriveDescription.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QString>

#include <array>
#include <functional>
#include <memory>
#include <optional>

namespace DriveDesk {

class DriveClient;
class ParameterModel;

// One step of a change to a parameter: one value written to the sets of a mask (service 0), or
// those sets reset to their default (service 32).
struct WriteStep
{
    quint8 setMask = 0;
    qint32 raw = 0; // not used by a reset
    bool reset = false;
};

// What became of a change.
struct WriteOutcome
{
    quint16 address = 0;
    quint8 acknowledgedMask = 0; // sets whose write the drive acknowledged
    quint8 refusedMask = 0; // sets whose write was refused or never answered
    QString error; // the first refusal or transport failure, in words
    bool connectionFailed = false; // no answer at all: later requests will fail alike
    QString readBackError; // acknowledged, but the value could not be read back
    // The drive's values (as the model held them) when the change began; per set, or [0].
    std::array<std::optional<qint32>, kParameterSets> before {};

    bool ok() const { return refusedMask == 0 && error.isEmpty(); }
};

// Carries changes of parameter values to the drive and reads every set it wrote back, telling
// the model each cell's outcome: pending at once, then written or failed with the drive's
// reason. The changes of one parameter run one after the other; the read-back of a change that
// a later one of the same parameter follows only stores the value, so the later one's cells
// never show a failure that is not theirs. Lives in the GUI thread.
class ValueWriter : public QObject
{
    Q_OBJECT
public:
    using Done = std::function<void(const WriteOutcome &)>;

    ValueWriter(DriveClient *client, ParameterModel *model, QObject *parent = nullptr);
    ~ValueWriter() override;

    // Parameters that are not set-programmable are written as set 0 (mask 01h) whatever the
    // masks say. `done` runs once, after the read-back; at once for an unknown parameter.
    void apply(quint16 address, QList<WriteStep> steps, Done done);
    // Changes given to apply() and not yet done.
    int runningCount() const { return m_running; }

signals:
    void runningCountChanged(int count);

private:
    struct Change
    {
        quint16 address = 0;
        QList<WriteStep> steps;
        Done done;
        WriteOutcome outcome;
        qsizetype nextStep = 0;
        int readsOnTheWay = 0;
    };
    using ChangePtr = std::shared_ptr<Change>;

    void markPending(const Change &change);
    void begin(const ChangePtr &change);
    void sendStep(const ChangePtr &change);
    void readBack(const ChangePtr &change);
    void finish(const ChangePtr &change);
    // A later change of the same parameter waits: it will write and read these cells again.
    bool isSuperseded(const Change &change) const;
    void setRunning(int count);

    DriveClient *m_client = nullptr;
    ParameterModel *m_model = nullptr;
    QHash<quint16, QList<ChangePtr>> m_queues; // per parameter; the first one is on its way
    int m_running = 0;
};

} // namespace DriveDesk
