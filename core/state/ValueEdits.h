#pragma once

#include "session/ValueChange.h"

#include <QHash>
#include <QList>
#include <QObject>

#include <array>
#include <functional>
#include <memory>
#include <optional>

namespace DriveDesk {

class DriveClient;
class DriveState;

// One edit of one parameter: what was sent and what became of it.
struct EditOutcome : WriteOutcome
{
    bool reset = false; // reset to the default (service 32), not a value written
    // As sent: the sets after SetList::setsWritten(), a reset's value the parameter's default.
    QList<WriteStep> steps;
    // The values held when the edit began, per set ([0] alone without sets), for undo; known
    // only where ValueEdits keeps a DriveState that holds the parameter.
    std::array<std::optional<qint32>, kParameterSets> before {};
    // Sets read back holding something else than was written (bit 0 also for the active set).
    // Never set for a parameter whose read-back may differ by its nature (readBackMayDiffer).
    quint8 differingMask = 0;
    // A later edit of the same parameter was waiting: it writes and reads these sets again, so
    // this outcome's refusals are no longer the cells' to show.
    bool superseded = false;

    // The sets the steps wrote (0: the active set alone).
    quint8 askedMask() const;
    // The value written to `set` (for a step with mask 0, to [0]: the active set).
    std::optional<qint32> asked(int set) const;
    // Written everywhere asked, read back, and the drive holds what was written.
    bool complete() const { return ok() && readBackError.isEmpty() && differingMask == 0; }
};

// A drive's pending edits, the one path a value edit takes to the drive and back for the
// window and the command line alike. Each edit is queued behind the earlier ones of the same
// parameter, applies the set-0 rule (SetList::setsWritten), is written and read back as a
// WriteValueJob in the client's thread, and ends in one EditOutcome (EditText says it in
// words). The drive's DriveState, where one is given, shows it all: the cells pending at once,
// then the outcome. Lives in the thread that made it; the client and the state outlive it.
class ValueEdits : public QObject
{
    Q_OBJECT
public:
    using Done = std::function<void(const EditOutcome &)>;

    // `state`: the drive's state, which takes the edits' pending values and outcomes and gives
    // EditOutcome::before; none where nothing else keeps the drive's values.
    explicit ValueEdits(DriveClient *client, DriveState *state = nullptr,
                        QObject *parent = nullptr);
    ~ValueEdits() override;

    // `raw` into the sets of the mask; mask 0 writes the active set (service 1).
    void write(const ParameterDescription &parameter, quint8 setMask, qint32 raw, Done done = {});
    void resetToDefault(const ParameterDescription &parameter, quint8 setMask, Done done = {});
    // Any steps, as undo and redo give them. `done` runs once, after the read-back.
    void apply(const ParameterDescription &parameter, QList<WriteStep> steps, bool reset,
               Done done = {});

    // Edits given and not yet done.
    int runningCount() const { return m_running; }

signals:
    // An edit was queued: the cells of the mask show `raw` until its outcome comes.
    void pending(quint16 address, quint8 setMask, qint32 raw);
    // What became of an edit; emitted before its `done` runs.
    void edited(const DriveDesk::EditOutcome &outcome);
    void runningCountChanged(int count);

private:
    struct Edit
    {
        ValueChange change;
        bool judgeReadBack = true; // not for a parameter whose read-back may differ
        Done done;
        EditOutcome outcome;
    };
    using EditPtr = std::shared_ptr<Edit>;

    void begin(const EditPtr &edit);
    void finish(const EditPtr &edit, const WriteOutcome &outcome);
    void setRunning(int count);

    DriveClient *m_client = nullptr;
    DriveState *m_state = nullptr;
    QHash<quint16, QList<EditPtr>> m_queues; // per parameter; the first one is on its way
    int m_running = 0;
};

} // namespace DriveDesk
