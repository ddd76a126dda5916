#include "EditJournal.h"

#include "journal/Journal.h"
#include "link/ConnectionSettings.h"
#include "parameters/DriveIdentity.h"
#include "parameters/ParameterFormat.h"
#include "parameters/PasswordLevel.h"

namespace DriveDesk {

namespace {

JournalValue journalValue(const ParameterFormat &format, std::optional<qint32> raw)
{
    return raw ? JournalValue { raw, format.text(*raw) } : JournalValue {};
}

} // namespace

EditJournal::EditJournal(Journal *journal, JournalDrive drive, QString job)
    : m_journal(journal)
    , m_drive(std::move(drive))
    , m_job(std::move(job))
{ }

WriteOutcome EditJournal::notSent(quint16 address, quint8 setMask, const QString &reason)
{
    WriteOutcome outcome;
    outcome.address = address;
    outcome.refusedMask = outcome.notSentMask = setMask;
    outcome.error = reason;
    return outcome;
}

WriteOutcome EditJournal::notJournaled(quint16 address, quint8 setMask, const QString &error)
{
    return notSent(address, setMask, tr("the journal cannot record it: %1").arg(error));
}

JournalDrive EditJournal::driveOf(const ConnectionSettings &settings,
                                  const DriveDescription &drive)
{
    JournalDrive named;
    named.link = settings.target();
    named.protocol = protocolName(settings.protocol);
    if (settings.protocol != Protocol::Hsp5)
        named.address = settings.driveAddress;
    named.kind = DriveIdentity::shown(drive, "In", 0);
    named.softwareVersion = DriveIdentity::shown(drive, "In", 6);
    named.serialNumber = DriveIdentity::shown(drive, "In", 10);
    return named;
}

bool EditJournal::fail(const QString &reason, QString *error) const
{
    *error = m_remedy.isEmpty() ? reason : tr("%1 (%2)").arg(reason, m_remedy);
    return false;
}

std::optional<QList<EditJournal::Entry>>
EditJournal::begin(const QString &id, const ParameterDescription &parameter,
                   const QList<WriteStep> &steps, const Values &before, QString *error)
{
    const std::optional<QList<QList<Entry>>> entries
        = begin(m_drive, { Write { id, &parameter, steps, before } }, error);
    return entries ? std::optional(entries->constFirst()) : std::nullopt;
}

std::optional<QList<QList<EditJournal::Entry>>>
EditJournal::begin(const JournalDrive &drive, const QList<Write> &writes, QString *error)
{
    if (!m_unavailable.isEmpty()) {
        fail(m_unavailable, error);
        return std::nullopt;
    }
    QList<QList<Entry>> begun;
    const qint64 jobBefore = m_jobId;
    const bool stored = m_journal->transaction([&] {
        if (m_jobId == 0) {
            const std::optional<qint64> job = m_journal->beginJob(m_job);
            if (!job)
                return false;
            m_jobId = *job;
        }
        for (const Write &write : writes) {
            const ParameterFormat format(*write.parameter);
            QList<Entry> entries;
            for (const WriteStep &step : write.steps) {
                QList<std::optional<int>> sets;
                if (step.setMask == 0) {
                    sets << std::nullopt;
                } else {
                    for (int set = 0; set < kParameterSets; ++set) {
                        if (step.setMask & (1u << set))
                            sets << (write.parameter->isSetProgrammable() ? std::optional<int>(set)
                                                                          : std::nullopt);
                    }
                }
                for (const std::optional<int> &set : sets) {
                    JournalEntry entry;
                    entry.jobId = m_jobId;
                    entry.jobDescription = m_job;
                    entry.drive = drive;
                    entry.parameterId = write.id;
                    entry.parameterAddress = write.parameter->address;
                    entry.parameterName = write.parameter->name;
                    entry.set = set;
                    entry.password = write.parameter->address == kPasswordParameterAddress;
                    entry.before = journalValue(format, write.before[std::size_t(set.value_or(0))]);
                    entry.written = journalValue(format, step.raw);
                    const std::optional<qint64> id = m_journal->begin(entry);
                    if (!id)
                        return false;
                    entries << Entry { *id, set, step.raw, step.setMask == 0 };
                }
            }
            begun << entries;
        }
        return true;
    });
    if (!stored) {
        m_jobId = jobBefore; // a job made in the transaction undone is gone with it
        fail(m_journal->errorString(), error);
        return std::nullopt;
    }
    return begun;
}

void EditJournal::complete(const ParameterDescription &parameter, const QList<Entry> &entries,
                           const WriteOutcome &outcome)
{
    const ParameterFormat format(parameter);
    for (const Entry &entry : entries) {
        const int set = entry.set.value_or(0);
        const auto bit = quint8(1u << set);
        const bool active = entry.activeSet;
        const JournalValue readBack = journalValue(format, outcome.readBack[std::size_t(set)]);
        const bool acknowledged = active ? outcome.activeSetAcknowledged
                                         : (outcome.acknowledgedMask & bit) != 0;
        const bool unknown = active ? outcome.activeSetUnanswered
                                    : (outcome.unknownMask() & bit) != 0;
        if (acknowledged) {
            m_journal->complete(entry.id, readBack, JournalOutcome::Written);
        } else if (unknown) {
            m_journal->complete(entry.id, readBack, JournalOutcome::Unknown, outcome.error);
        } else if (!active && (outcome.notSentMask & bit)) {
            m_journal->complete(entry.id, readBack, JournalOutcome::Refused,
                                tr("not sent: %1").arg(outcome.error));
        } else {
            m_journal->complete(entry.id, readBack, JournalOutcome::Refused, outcome.error);
        }
    }
}

void EditJournal::completeTogether(const std::function<void()> &completions)
{
    const bool together = m_journal->transaction([&] {
        completions();
        return true;
    });
    // Undone or never begun (another program held the journal too long): each on its own,
    // as far as the journal takes them, rather than left unknown.
    if (!together)
        completions();
}

} // namespace DriveDesk
