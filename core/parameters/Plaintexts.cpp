#include "Plaintexts.h"

#include <algorithm>

namespace DriveDesk {

namespace {

QString hex(quint32 bits)
{
    return QString::number(bits, 16).toUpper().rightJustified(bits > 0xFFFF ? 8 : 4,
                                                              QLatin1Char('0'))
        + QLatin1Char('h');
}

const PlaintextEntry *findText(const PlaintextDefinition &definition, const QString &text)
{
    for (const PlaintextEntry &entry : definition.entries) {
        if (entry.text.trimmed().compare(text, Qt::CaseInsensitive) == 0)
            return &entry;
    }
    return nullptr;
}

} // namespace

const QString Plaintexts::kSeparator = QStringLiteral(" | ");

bool Plaintexts::isEmpty() const
{
    for (const PlaintextDefinition &definition : m_definitions) {
        if (!definition.entries.isEmpty())
            return false;
    }
    return true;
}

bool Plaintexts::isBitField() const
{
    return std::count_if(m_definitions.begin(), m_definitions.end(),
                         [](const PlaintextDefinition &d) { return !d.entries.isEmpty(); })
           > 1;
}

QString Plaintexts::shown(qint32 raw, bool withUnit) const
{
    if (!isEmpty() && (isBitField() || hasText(raw)))
        return text(raw);
    return m_scaling.format(raw, withUnit);
}

quint32 Plaintexts::effectiveMask(const PlaintextDefinition &definition)
{
    return definition.mask == 0 ? 0xFFFFFFFFu : definition.mask;
}

const PlaintextEntry *Plaintexts::match(const PlaintextDefinition &definition, qint32 raw)
{
    const quint32 mask = effectiveMask(definition);
    for (const PlaintextEntry &entry : definition.entries) {
        if ((quint32(entry.value) & mask) == (quint32(raw) & mask))
            return &entry;
    }
    return nullptr;
}

bool Plaintexts::hasText(qint32 raw) const
{
    if (m_definitions.size() == 1)
        return match(m_definitions.first(), raw) != nullptr;
    quint32 covered = 0;
    bool anyText = false;
    for (const PlaintextDefinition &definition : m_definitions) {
        const quint32 mask = effectiveMask(definition);
        covered |= mask;
        if (match(definition, raw))
            anyText = true;
        else if (quint32(raw) & mask)
            return false;
    }
    return anyText && (quint32(raw) & ~covered) == 0;
}

QString Plaintexts::unmatchedField(qsizetype index, quint32 bits) const
{
    const PlaintextDefinition &definition = m_definitions.at(index);
    const QString name = definition.description.isEmpty()
        ? tr("definition %1").arg(index)
        : QStringLiteral("'%1'").arg(definition.description);
    return tr("%1 (no plaintext in %2)").arg(hex(bits), name);
}

QString Plaintexts::text(qint32 raw) const
{
    if (isEmpty())
        return m_scaling.format(raw);
    const QString noText = tr("%1 (no plaintext)").arg(m_scaling.format(raw));
    if (m_definitions.size() == 1) {
        // Bits outside a single definition's mask are the drive's sign extension, not a field.
        const PlaintextEntry *entry = match(m_definitions.first(), raw);
        return entry ? entry->text : noText;
    }

    QStringList parts;
    quint32 covered = 0;
    for (qsizetype i = 0; i < m_definitions.size(); ++i) {
        const PlaintextDefinition &definition = m_definitions.at(i);
        const quint32 mask = effectiveMask(definition);
        covered |= mask;
        if (const PlaintextEntry *entry = match(definition, raw))
            parts << entry->text;
        else if (const quint32 bits = quint32(raw) & mask)
            parts << unmatchedField(i, bits);
    }
    if (const quint32 rest = quint32(raw) & ~covered)
        parts << tr("other bits %1").arg(hex(rest));
    return parts.isEmpty() ? noText : parts.join(kSeparator);
}

qint32 Plaintexts::withField(qint32 raw, qsizetype index, qint32 fieldValue) const
{
    Q_ASSERT(index >= 0 && index < m_definitions.size());
    const quint32 mask = effectiveMask(m_definitions.at(index));
    return qint32((quint32(raw) & ~mask) | (quint32(fieldValue) & mask));
}

QStringList Plaintexts::allowedTexts() const
{
    QStringList texts;
    for (const PlaintextDefinition &definition : m_definitions) {
        for (const PlaintextEntry &entry : definition.entries)
            texts << entry.text;
    }
    return texts;
}

QString Plaintexts::allowedList() const
{
    if (m_definitions.size() == 1)
        return allowedTexts().join(QStringLiteral(", "));
    QStringList groups;
    for (int i = 0; i < m_definitions.size(); ++i) {
        const PlaintextDefinition &definition = m_definitions.at(i);
        QStringList texts;
        for (const PlaintextEntry &entry : definition.entries)
            texts << entry.text;
        const QString name = definition.description.isEmpty() ? tr("definition %1").arg(i)
                                                              : definition.description;
        groups << QStringLiteral("%1: %2").arg(name, texts.join(QStringLiteral(", ")));
    }
    return groups.join(QStringLiteral("; "));
}

std::optional<qint32> Plaintexts::value(const QString &input, QString *error, qint32 current) const
{
    auto fail = [error](const QString &message) -> std::optional<qint32> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QString text = input.trimmed();
    if (isEmpty())
        return fail(tr("this parameter has no plaintexts"));
    const QString unknown = tr("'%1' is not a plaintext of this parameter; allowed: %2");
    if (text.isEmpty())
        return fail(tr("no text given; allowed: %1").arg(allowedList()));

    if (m_definitions.size() == 1) {
        const PlaintextDefinition &definition = m_definitions.first();
        const PlaintextEntry *entry = findText(definition, text);
        if (!entry)
            return fail(unknown.arg(text, allowedList()));
        const quint32 mask = effectiveMask(definition);
        if (quint32(entry->value) & ~mask)
            return entry->value; // the drive gave the whole value (e.g. sign-extended)
        return qint32((quint32(current) & ~mask) | quint32(entry->value));
    }

    QStringList parts = text.split(QLatin1Char('|'));
    for (QString &part : parts) {
        part = part.trimmed();
        if (part.isEmpty())
            return fail(tr("'%1' has an empty text between '|'").arg(text));
    }
    const qsizetype count = m_definitions.size();
    QList<const PlaintextEntry *> chosen(count, nullptr);

    // The form text() writes: one text per definition, in order.
    bool positional = parts.size() == count;
    for (qsizetype i = 0; positional && i < count; ++i) {
        chosen[i] = findText(m_definitions.at(i), parts.at(i));
        positional = chosen[i] != nullptr;
    }
    if (!positional) {
        chosen.fill(nullptr);
        for (const QString &part : std::as_const(parts)) {
            QList<qsizetype> owners;
            for (qsizetype i = 0; i < count; ++i) {
                if (findText(m_definitions.at(i), part))
                    owners << i;
            }
            if (owners.isEmpty())
                return fail(unknown.arg(part, allowedList()));
            QList<qsizetype> free;
            for (qsizetype i : std::as_const(owners)) {
                if (!chosen.at(i))
                    free << i;
            }
            if (free.isEmpty()) {
                return fail(tr("'%1' and '%2' are texts of the same definition")
                                .arg(chosen.at(owners.first())->text, part));
            }
            if (free.size() > 1) {
                return fail(tr("'%1' is a text of several definitions: give one text for "
                               "each definition, in order (%2)")
                                .arg(part, allowedList()));
            }
            chosen[free.first()] = findText(m_definitions.at(free.first()), part);
        }
    }

    quint32 covered = 0;
    quint32 result = 0;
    for (qsizetype i = 0; i < count; ++i) {
        const quint32 mask = effectiveMask(m_definitions.at(i));
        covered |= mask;
        if (chosen.at(i))
            result |= quint32(chosen.at(i)->value) & mask;
    }
    return qint32(result | (quint32(current) & ~covered));
}

} // namespace DriveDesk
