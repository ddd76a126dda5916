#include "PlaintextTable.h"

#include "DataText.h"

namespace DriveDesk::Sim {

namespace {

// A parameter id ("ru.00") rather than an enumeration name.
bool isParameterId(const QString &key)
{
    return key.contains(QLatin1Char('.'));
}

} // namespace

PlaintextTable PlaintextTable::load(const CsvTable &table, QStringList &problems)
{
    PlaintextTable result;
    result.m_fileName = table.fileName();
    for (const CsvTable::Row &row : table.rows()) {
        const QString where = QStringLiteral("%1:%2").arg(table.fileName()).arg(row.line);
        const QString key = table.cell(row, QStringLiteral("key"));
        Row entry;
        entry.line = row.line;
        const QString mask = table.cell(row, QStringLiteral("mask"));
        if (!mask.isEmpty()) {
            bool ok = false;
            entry.mask = mask.toUInt(&ok, 16);
            if (!ok || entry.mask == 0) {
                problems
                    << QStringLiteral("%1: mask \"%2\" is not a hex bit mask").arg(where, mask);
                continue;
            }
        }
        const std::optional<qint32> value = parseNumber(table.cell(row, QStringLiteral("value")));
        if (key.isEmpty() || !value) {
            problems
                << QStringLiteral("%1: a plaintext needs a key and a numeric value").arg(where);
            continue;
        }
        if ((quint32(*value) & ~entry.mask) != 0) {
            problems << QStringLiteral("%1: value %2 has bits outside mask %3")
                            .arg(where)
                            .arg(*value)
                            .arg(entry.mask, 0, 16);
            continue;
        }
        entry.value = *value;
        entry.descriptionEn = table.cell(row, QStringLiteral("definition_en"));
        entry.descriptionDe = table.cell(row, QStringLiteral("definition_de"));
        entry.display = table.cell(row, QStringLiteral("display"));
        entry.textEn = table.cell(row, QStringLiteral("text_en"));
        entry.textDe = table.cell(row, QStringLiteral("text_de"));
        if (!isParameterId(key) && (entry.textEn.isEmpty() || entry.textDe.isEmpty())) {
            problems << QStringLiteral("%1: plaintext of \"%2\" needs an English and a German text")
                            .arg(where, key);
            continue;
        }
        if (!result.m_rows.contains(key))
            result.m_keys << key;
        result.m_rows[key].append(entry);
    }
    return result;
}

Plaintext PlaintextTable::makePlaintext(qint32 value, const QString &english, const QString &german,
                                        const QString &display, const QString &where,
                                        QStringList &problems)
{
    Plaintext text;
    text.value = value;
    text.text[0] = lineText(english, where + QStringLiteral(": English text"), problems);
    text.text[1] = lineText(german.isEmpty() ? english : german,
                            where + QStringLiteral(": German text"), problems);
    if (!display.isEmpty()) {
        const std::optional<SegmentPattern> pattern = sevenSegmentPattern(display);
        if (pattern)
            text.display = *pattern;
        else
            problems << QStringLiteral("%1: display text \"%2\" does not fit five 7-segment digits")
                            .arg(where, display);
    } else {
        // The first word of the English text, as far as the display can show it.
        QString word = english.section(QLatin1Char(' '), 0, 0);
        std::optional<SegmentPattern> pattern = sevenSegmentPattern(word);
        while (!pattern && !word.isEmpty()) {
            word.chop(1);
            pattern = sevenSegmentPattern(word);
        }
        text.display = pattern.value_or(SegmentPattern {});
    }
    // Error and warning states replace what the display shows (plaintext type bit 1).
    const QString shown = display.isEmpty() ? english : display;
    if (shown.startsWith(QLatin1String("E.")) || shown.startsWith(QLatin1String("A.")))
        text.type = 0x02;
    return text;
}

std::optional<Enumeration> PlaintextTable::enumeration(const QString &key,
                                                       QStringList &problems) const
{
    if (isParameterId(key) || !m_rows.contains(key))
        return std::nullopt;
    Enumeration result;
    for (const Row &row : m_rows.value(key)) {
        const QString where = QStringLiteral("%1:%2").arg(m_fileName).arg(row.line);
        PlaintextDefinitionEntry *definition = nullptr;
        for (PlaintextDefinitionEntry &d : result.definitions) {
            if (d.mask == row.mask)
                definition = &d;
        }
        if (!definition) {
            result.definitions.append(PlaintextDefinitionEntry { row.mask, {}, {} });
            definition = &result.definitions.last();
        }
        if (definition->description[0].isEmpty() && !row.descriptionEn.isEmpty()) {
            definition->description[0]
                = lineText(row.descriptionEn, where + QStringLiteral(": definition"), problems);
            definition->description[1]
                = lineText(row.descriptionDe.isEmpty() ? row.descriptionEn : row.descriptionDe,
                           where + QStringLiteral(": definition"), problems);
        }
        definition->texts.append(
            makePlaintext(row.value, row.textEn, row.textDe, row.display, where, problems));
    }
    for (const PlaintextDefinitionEntry &d : result.definitions) {
        if (result.definitions.size() > 1 && d.description[0].isEmpty())
            problems << QStringLiteral("%1: definition %2 of \"%3\" has no description")
                            .arg(m_fileName)
                            .arg(d.mask, 0, 16)
                            .arg(key);
    }
    return result;
}

Enumeration PlaintextTable::fromFacts(const QString &id, const QString &factsCell,
                                      QStringList &problems) const
{
    PlaintextDefinitionEntry definition;
    QList<qint32> values;
    const QList<Row> changes = m_rows.value(id);
    for (const QString &pair : factsCell.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const qsizetype eq = pair.indexOf(QLatin1Char('='));
        bool ok = false;
        const qint32 value = eq > 0 ? pair.left(eq).trimmed().toInt(&ok) : 0;
        if (!ok)
            continue; // prose: a range or a bit description, not a plaintext
        QString english = pair.mid(eq + 1).trimmed();
        QString german;
        QString display = english.section(QLatin1String(" ("), 0, 0);
        for (const Row &change : changes) {
            if (change.value != value)
                continue;
            if (!change.textEn.isEmpty())
                english = change.textEn;
            german = change.textDe;
            if (!change.display.isEmpty())
                display = change.display;
        }
        const QString where = QStringLiteral("%1 value %2").arg(id).arg(value);
        definition.texts.append(makePlaintext(value, english, german, display, where, problems));
        values << value;
    }
    for (const Row &change : changes) {
        if (!values.contains(change.value))
            problems << QStringLiteral(
                            "%1:%2: %3 has no plaintext for value %4 in keb_f5_params.csv")
                            .arg(m_fileName)
                            .arg(change.line)
                            .arg(id)
                            .arg(change.value);
    }
    if (definition.texts.isEmpty())
        problems << QStringLiteral("%1: keb_f5_params.csv gives no value=text plaintexts").arg(id);
    Enumeration result;
    result.definitions.append(definition);
    return result;
}

QStringList PlaintextTable::unusedKeys(const QStringList &used) const
{
    QStringList unused;
    for (const QString &key : m_keys) {
        if (!used.contains(key))
            unused << key;
    }
    return unused;
}

} // namespace DriveDesk::Sim
