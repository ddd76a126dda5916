#pragma once

#include "parameters/DriveDescription.h"
#include "session/ValueChange.h"

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

// A change's outcome as the window needs it: the drive's values (as the model held them) when
// the change began, per set or [0], for undo.
struct EditOutcome : WriteOutcome
{
    std::array<std::optional<qint32>, kParameterSets> before{};
};

// Shows a change's outcome in the model's cells: failed with the drive's reason, or the value
// read back (written when it is what was asked for). A change that a later one of the same
// parameter supersedes only stores the values read, so the later one's cells never show a
// failure that is not theirs.
void showOutcome(ParameterModel &model, const WriteOutcome &outcome, bool superseded = false);

// Carries changes of parameter values to the drive, each as a WriteValueJob (written, then
// read back, in the client's thread), telling the model each cell's outcome: pending at once,
// then written or failed with the drive's reason. The changes of one parameter run one after
// the other (see showOutcome() for the superseded ones). Lives in the GUI thread.
class ValueWriter : public QObject
{
    Q_OBJECT
public:
    using Done = std::function<void(const EditOutcome &)>;

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
        EditOutcome outcome;
    };
    using ChangePtr = std::shared_ptr<Change>;

    void markPending(const Change &change);
    void begin(const ChangePtr &change);
    void written(const ChangePtr &change, const WriteOutcome &outcome);
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
