// CliRunner: `read` and `write` of one parameter, a write through the window's edit path and,
// unless --no-journal, into the journal.
#include "CliRunner.h"

#include "client/WhenFinished.h"
#include "journal/Journal.h"
#include "parameters/ParameterFormat.h"
#include "parameters/ParameterId.h"
#include "session/EditJournal.h"
#include "state/DriveState.h"
#include "state/EditCheck.h"
#include "state/EditText.h"
#include "state/ValueEdits.h"

#include <algorithm>

namespace DriveDesk {

void CliRunner::runRead()
{
    lookUpParameter([this](const GroupDescription &group, const ParameterDescription &parameter) {
        const QString id = parameterId(group, parameter);
        QFuture<Reply> reply = m_request.set
                                   ? m_client->readValue(parameter.address, quint8(1u << *m_request.set))
                                   : m_client->readValueStandard(parameter.address, 0);
        const QString where = m_request.set ? tr("set %1").arg(*m_request.set) : tr("active set");
        whenFinished(reply, this, [this, id, where, parameter](const Reply &r) {
            if (!r.ok())
                return fail(1, QStringLiteral("%1: %2").arg(id, r.message()));
            const qint32 raw = r.data<ParameterValue>()->value;
            m_out << tr("%1  %2 = %3  (raw %4, %5)")
                         .arg(id, parameter.name, valueText(parameter, raw))
                         .arg(raw)
                         .arg(where)
                  << '\n';
            done();
        }, [this] { connectionClosed(); });
    });
}

void CliRunner::runWrite()
{
    lookUpParameter([this](const GroupDescription &group, const ParameterDescription &parameter) {
        const QString id
            = ParameterId::format(parameter.address, GroupAddress{group.id, group.address});
        // The window's rule (EditCheck) at the level the drive enforces itself: a plaintext or
        // a number in display units (or a raw integer with --raw), refused when it cannot be
        // held exactly or lies outside the limits.
        const ParameterState state(parameter, id);
        if (const QString refusal = EditCheck::refusal(state, PasswordLevel::Supervisor);
            !refusal.isEmpty())
            return fail(2, tr("%1; nothing was written").arg(refusal));
        const ParameterFormat format = m_request.raw ? state.format().rawFormat() : state.format();
        QString error;
        const std::optional<qint32> raw = format.parse(m_request.value, &error);
        if (!raw)
            return fail(2, tr("%1: %2; nothing was written").arg(id, error));
        if (const QString refusal = EditCheck::valueRefusal(state, *raw, PasswordLevel::Supervisor);
            !refusal.isEmpty())
            return fail(2, tr("%1; nothing was written").arg(refusal));
        if (!m_request.journalWrites)
            return writeValue(id, parameter, true, *raw);
        // The journal names the drive by what it says it is.
        readIdentity(parameter.address,
                     [this, id, parameter, raw = *raw] { writeValue(id, parameter, true, raw); });
        return;
        writeValue(id, parameter, true, *raw);
    });
}

bool CliRunner::openJournal(QString *error)
{
    m_journal = std::make_unique<Journal>(m_request.journalPath);
    if (m_journal->open())
        return true;
    *error = m_journal->errorString();
    return false;
}

void CliRunner::readIdentity(quint16 address, std::function<void()> next)
{
    ScanOptions identity;
    identity.groupPages = { quint8(address >> 8) };
    identity.onlyParameters = { address };
    if (const GroupDescription *in = m_state->description().findGroup(QStringLiteral("In"))) {
        identity.groupPages << quint8(in->address >> 8);
        for (const quint8 number : { 0, 6, 10 })
            identity.onlyParameters << quint16(in->address | number);
    }
    scan(identity, [this, next = std::move(next)](const DriveDescription &found) {
        // What could not be read leaves the journal's entry without it, not the write undone.
        // The values read just now join what the state knows: the identification, and the
        // value before the write.
        DriveDescription drive = m_state->description();
        for (const GroupDescription &group : found.groups) {
            auto known = std::find_if(drive.groups.begin(), drive.groups.end(),
                                      [&group](const GroupDescription &g) { return g.id == group.id; });
            if (known == drive.groups.end()) {
                drive.groups << group;
                continue;
            }
            for (const ParameterDescription &read : group.parameters) {
                ParameterDescription *held = drive.find(read.address);
                if (!held)
                    known->parameters << read;
                else if (read.error.isEmpty())
                    held->values = read.values;
            }
        }
        m_state->setDescription(drive);
        next();
    });
}

// The window's edit path: a write counts only once the drive shows the value, and the outcome
// is said in the window's words.
void CliRunner::writeValue(const QString &id, const ParameterDescription &parameter,
                           bool described, qint32 raw)
{
    auto *edits = new ValueEdits(m_client.get(), m_state, this);
    if (m_request.journalWrites) {
        QString error;
        if (!openJournal(&error)) {
            edits->deleteLater();
            return fail(1, tr("%1 not written: %2 (--no-journal writes without it)").arg(id, error));
        }
        m_editJournal = std::make_unique<EditJournal>(
            m_journal.get(), EditJournal::driveOf(m_request.connection, m_state->description()),
            tr("write %1").arg(id));
        edits->setJournal(m_editJournal.get());
    }
    edits->write(parameter, m_request.setMask, raw,
                 [this, edits, id, parameter, described](const EditOutcome &outcome) {
                     edits->deleteLater();
                     const QString text
                         = EditText(id, described ? &parameter : nullptr).outcome(outcome);
                     // Unknown is no refusal: the drive did not answer (exit 3, as a
                     // drive that stopped answering).
                     if (!outcome.complete())
                         return fail(outcome.anyUnknown() ? 3 : 1, text);
                     m_out << text << '\n';
                     done();
                 });
}

} // namespace DriveDesk
