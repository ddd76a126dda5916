#include "RunJournal.h"

#include "journal/Journal.h"
#include "session/EditJournal.h"

#include <QObject>

#include <memory>

namespace DriveDesk {

EditJournal *RunJournal::attach(QObject *run, const QString &job)
{
    auto journal = std::make_shared<Journal>();
    auto entries = std::make_shared<EditJournal>(journal.get(), JournalDrive {}, job);
    if (!journal->open())
        entries->setUnavailable(journal->errorString());
    entries->setRemedy(tr("Drive > Journal Every Write off writes without it"));
    // Both go when the run does: its connection is dropped, and the lambda with it.
    QObject::connect(run, &QObject::destroyed, run, [journal, entries] { });
    return entries.get();
}

} // namespace DriveDesk
