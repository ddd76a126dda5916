#pragma once

#include "frame/ParameterEditing.h"
#include "ValueReadBatch.h"
#include "ValueCommand.h"

#include "session/CopySet.h"
#include "state/ValueEdits.h"

#include <QHash>
#include <QObject>
#include <QPointer>

#include <memory>

class QUndoStack;

namespace DriveDesk {

class DriveClient;
class ParameterModel;

// Carries the user's edits to the drive through core's ValueEdits: writes and resets to
// default as undoable commands, each read back so that the model shows what the drive holds
// (written, or failed with the drive's reason); copying one set to another; re-reading every
// value. A value that only came
// from the drive is never written back to it. Lives in the GUI thread; the client, the model and
// the undo stack outlive it.
class EditController : public QObject, public ParameterEditing, public ValueCommand::Host
{
    Q_OBJECT
public:
    EditController(DriveClient *client, ParameterModel *model, QUndoStack *undoStack,
                   QObject *parent = nullptr);
    ~EditController() override;

    // Connected to ParameterModel::valueEdited by the controller itself. The cells show pending
    // at once (ValueEdits::pending); the command goes on the undo stack once the drive has
    // acknowledged the write, so a refused write never stands there as if it had happened.
    void write(quint16 address, quint8 setMask, qint32 raw);
    // Service 32 write, then read back; undoable (the earlier values are written back).
    void resetToDefault(quint16 address, quint8 setMask) override;
    // Every set-programmable parameter the user may edit whose value in `toSet` differs from
    // `fromSet`'s; one step on the undo stack (what was written before a cancel or a refusal).
    void copySet(int fromSet, int toSet) override;
    // Re-reads every value the level in force lets be read (F5). A read the drive refuses is
    // kept per cell (readFailure) and the refresh goes on.
    void refresh();
    // Reads these values (a higher password level opened them); after a refresh or copy on its
    // way, if one is.
    void readAgain(const QList<ValueRead> &reads);
    // Stops a copy or refresh after the requests on their way; what was done stays done.
    void cancel();
    // The drive holds none of what was written any more (the built-in simulated drive starts
    // afresh on every connection): the written marks and the undo history go.
    void forgetWrites();

    // Every edit from now on is journaled there (ValueEdits::setJournal); none: not journaled.
    void setJournal(EditJournal *journal) { m_edits->setJournal(journal); }

    bool isBusy() const override { return m_busy; }
    ValueEdits *driveEdits() const override { return m_edits; }
    // Why the last refresh could not read this value, or empty.
    QString readFailure(quint16 address, int set) const;
    int readFailureCount() const { return int(m_readFailures.size()); }

signals:
    void message(const QString &text); // for the status bar: results and refusals in words
    void busyChanged(bool busy);
    void progress(int done, int total); // of a copy or refresh

private:
    // copySet() while its batch runs through ValueEdits.
    struct CopyJob
    {
        CopySetPlan plan;
        quint64 batch = 0; // ValueEdits::applyAll()'s
        std::unique_ptr<QUndoCommand> macro; // the values written, one step on the stack
        int answered = 0; // items the drive was asked and answered
        int written = 0;
        QStringList refusals;
        QString stopReason;
        bool cancelled = false;
    };

    // Undo or redo of a command on the stack: to the drive and back.
    void perform(ValueCommand *command, ValueCommand::Direction direction) override;
    void performed(ValueCommand *command, const std::weak_ptr<const int> &alive,
                   ValueCommand::Direction direction, const EditOutcome &outcome);
    void changeDone(const EditOutcome &outcome);
    // The undo history's name of a change: "Write op.11 = 2500 1/min (set 2)".
    QString commandText(ValueCommand::Kind kind, quint16 address, quint8 setMask,
                        qint32 raw) const;

    void copyTake(qsizetype index, const EditOutcome &outcome);
    void copyFinished(const QList<EditOutcome> &outcomes);
    void refreshFinished();
    void startReads(const QList<ValueRead> &reads);
    void startQueuedReads();
    bool refuseWhileJobRuns();

    void updateBusy();

    DriveClient *m_client = nullptr;
    ParameterModel *m_model = nullptr;
    QUndoStack *m_undoStack = nullptr;
    ValueEdits *m_edits = nullptr; // child
    QPointer<ValueReadBatch> m_refresh; // child while a refresh runs
    std::unique_ptr<CopyJob> m_copy;
    QHash<quint32, QString> m_readFailures; // address << 8 | set
    QList<ValueRead> m_queuedReads; // readAgain() while a job ran
    bool m_busy = false;
};

} // namespace DriveDesk
