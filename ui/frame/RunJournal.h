#pragma once

#include <QCoreApplication>
#include <QString>

class QObject;

namespace DriveDesk {

class EditJournal;

// The window's journal (docs/journal.md) for one job that writes to drives beside the edits (a
// download, a plant's download), while Drive > Journal Every Write is on: a connection of the
// job's own that lives as long as `run`, whatever the setting or the session do meanwhile. A
// journal that cannot be written refuses the job's entries with the reason and how to write
// without it, so that the job stops before it writes. Thread: the run's.
class RunJournal
{
    Q_DECLARE_TR_FUNCTIONS(RunJournal)
public:
    // `job`: how the journal names it ("download of f5.json").
    static EditJournal *attach(QObject *run, const QString &job);
};

} // namespace DriveDesk
