#pragma once

#include "parameters/DriveDescription.h"

#include <QCoreApplication>
#include <QString>

namespace DriveDesk {

struct EditOutcome;

// How messages name one parameter's edit, in the window, in a parameter file and on the command
// line alike: the id ("op.11"), values as the drive shows them (a password never), the sets in
// parentheses, and what became of an edit sent to the drive.
class EditText
{
    Q_DECLARE_TR_FUNCTIONS(EditText)
public:
    // Without a description (a parameter the drive does not have, DIN66019) values are shown
    // raw and the sets always named. The description must outlive this object.
    EditText(QString id, const ParameterDescription *parameter);

    const QString &id() const { return m_id; }
    QString value(qint32 raw) const;
    // " (set 2)", " (sets 0, 3)", " (all sets)", " (active set)" for mask 0, or nothing for a
    // parameter without sets. A note in parentheses takes no part in the sentence's grammar, so
    // every language can append it where the sentence names the parameter or the value.
    QString inSets(quint8 setMask) const;

    // "op.11 = 2500 1/min written (set 2)", "op.11 reset to its default (sets 0, 1)" or
    // "op.11 = 2500 1/min not written (set 2): <reason>", then the sets refused and
    // readBackNotes().
    QString outcome(const EditOutcome &outcome) const;
    // "; reading it back failed: <reason>", "; the drive holds 2499 1/min (set 2)", or empty.
    QString readBackNotes(const EditOutcome &outcome) const;

private:
    QString m_id;
    const ParameterDescription *m_parameter = nullptr;
};

} // namespace DriveDesk
