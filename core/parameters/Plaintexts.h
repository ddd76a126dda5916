#pragma once

#include "DisplayScaling.h"
#include "DriveDescription.h"

#include <QCoreApplication>
#include <QStringList>

#include <optional>

namespace DriveDesk {

// Turns a raw value into its plaintext and back through a parameter's plaintext definitions
// (services 7, 9, 12; seed 002 chapter 3).
//
// Entry values are "in place": they already sit on the bits of their definition's mask, so an
// entry matches a raw value when (raw & mask) == (entry & mask). Bits outside the mask are
// ignored on both sides, so a sign-extended -1 with mask FFFFh matches raw FFFFh. A mask of 0
// would cover no bits and is taken as FFFFFFFFh: the definition is then a plain enumeration.
//
// With one definition the text is that of the matching entry. With several (a bit-field
// parameter) each definition gives one text and the texts are joined " | "; a field whose bits
// are all clear and that has no text for 0 says nothing, and bits outside every mask are named.
// Bits outside a single definition's mask are not named: they are the drive's sign extension.
class Plaintexts
{
    Q_DECLARE_TR_FUNCTIONS(Plaintexts)
public:
    static const QString kSeparator; // " | "

    Plaintexts() = default;
    explicit Plaintexts(QList<PlaintextDefinition> definitions, DisplayScaling scaling = {})
        : m_definitions(std::move(definitions))
        , m_scaling(scaling)
    { }

    const QList<PlaintextDefinition> &definitions() const { return m_definitions; }
    // No entry in any definition: the parameter shows numbers only.
    bool isEmpty() const;
    static quint32 effectiveMask(const PlaintextDefinition &definition);

    // The entry of `definition` for the raw value's bits, or nothing.
    static const PlaintextEntry *match(const PlaintextDefinition &definition, qint32 raw);
    // Every bit of the value is explained by a text.
    bool hasText(qint32 raw) const;
    // The plaintext; where a text is missing, the scaled number and "(no plaintext)".
    QString text(qint32 raw) const;
    // Several definitions with texts: the value holds bit fields.
    bool isBitField() const;
    // The value as the drive shows it, for every view of it (table, editor, command line): a
    // bit field names each field; an enumeration its text, or the scaled number where it has
    // none for this value; a parameter without texts the scaled number.
    QString shown(qint32 raw, bool withUnit = true) const;

    // The raw value for a text (case-insensitive, exact). With several definitions "A | B":
    // each part picks an entry of a different definition; definitions not named are 0; bits
    // outside every mask are kept from `current`. With one definition: the entry's value, the
    // bits outside the mask kept from `current` unless the entry's value sets them itself.
    std::optional<qint32> value(const QString &text, QString *error = nullptr,
                                qint32 current = 0) const;

    // A bit-field value with one field chosen: the bits under the mask of definition `index`
    // taken from `fieldValue` (in place, as entry values are), every other bit kept from `raw`.
    // How an editor of the fields composes the value, one field at a time.
    qint32 withField(qint32 raw, qsizetype index, qint32 fieldValue) const;

    // Every text in definition order, e.g. for a combo box.
    QStringList allowedTexts() const;

private:
    QString unmatchedField(qsizetype index, quint32 bits) const;
    QString allowedList() const;

    QList<PlaintextDefinition> m_definitions;
    DisplayScaling m_scaling;
};

} // namespace DriveDesk
