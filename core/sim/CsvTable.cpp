#include "CsvTable.h"

#include <QFile>

namespace DriveDesk::Sim {

namespace {

// Splits one record that starts at `pos`; advances `pos` past its line end and counts lines.
// Returns false on an unterminated quote.
bool splitRecord(const QString &text, qsizetype &pos, int &line, QStringList &cells)
{
    QString cell;
    bool quoted = false;
    bool afterQuote = false;
    while (pos < text.size()) {
        const QChar c = text.at(pos);
        if (quoted) {
            if (c == QLatin1Char('"')) {
                if (pos + 1 < text.size() && text.at(pos + 1) == QLatin1Char('"')) {
                    cell += c;
                    ++pos;
                } else {
                    quoted = false;
                    afterQuote = true;
                }
            } else {
                if (c == QLatin1Char('\n'))
                    ++line;
                cell += c;
            }
            ++pos;
            continue;
        }
        if (c == QLatin1Char('"') && cell.isEmpty() && !afterQuote) {
            quoted = true;
        } else if (c == QLatin1Char(',')) {
            cells << cell;
            cell.clear();
            afterQuote = false;
        } else if (c == QLatin1Char('\n')) {
            ++pos;
            ++line;
            cells << cell;
            return true;
        } else if (c != QLatin1Char('\r')) {
            cell += c;
        }
        ++pos;
    }
    if (quoted)
        return false;
    cells << cell;
    return true;
}

} // namespace

CsvTable CsvTable::parse(const QString &text, const QString &fileName)
{
    CsvTable table;
    table.m_fileName = fileName;
    qsizetype pos = 0;
    int line = 1;
    bool haveHeader = false;
    while (pos < text.size()) {
        const int startLine = line;
        if (text.at(pos) == QLatin1Char('#') || text.at(pos) == QLatin1Char('\n')
            || text.at(pos) == QLatin1Char('\r')) {
            const qsizetype end = text.indexOf(QLatin1Char('\n'), pos);
            pos = end < 0 ? text.size() : end + 1;
            ++line;
            continue;
        }
        QStringList cells;
        if (!splitRecord(text, pos, line, cells)) {
            table.m_problems
                << QStringLiteral("%1:%2: unterminated quoted cell").arg(fileName).arg(startLine);
            break;
        }
        if (!haveHeader) {
            for (int i = 0; i < cells.size(); ++i)
                table.m_columns.insert(cells.at(i).trimmed(), i);
            haveHeader = true;
            continue;
        }
        if (cells.size() != table.m_columns.size()) {
            table.m_problems << QStringLiteral("%1:%2: %3 cells, the header has %4")
                                    .arg(fileName)
                                    .arg(startLine)
                                    .arg(cells.size())
                                    .arg(table.m_columns.size());
            continue;
        }
        table.m_rows.append(Row { startLine, cells });
    }
    if (!haveHeader)
        table.m_problems << QStringLiteral("%1: no header row").arg(fileName);
    return table;
}

CsvTable CsvTable::read(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        CsvTable table;
        table.m_fileName = path;
        table.m_problems << QStringLiteral("%1: cannot be read: %2").arg(path, file.errorString());
        return table;
    }
    return parse(QString::fromUtf8(file.readAll()), path);
}

QString CsvTable::cell(const Row &row, const QString &column) const
{
    const int index = m_columns.value(column, -1);
    if (index < 0 || index >= row.cells.size())
        return QString();
    return row.cells.at(index).trimmed();
}

} // namespace DriveDesk::Sim
