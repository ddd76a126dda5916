#pragma once

#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>

namespace DriveDesk::Sim {

// A CSV file with a header row, as the simulated drive's data files are written (RFC 4180
// quoting; lines starting with '#' are comments).
class CsvTable
{
public:
    struct Row
    {
        int line = 0; // 1-based line in the file, for messages
        QStringList cells;
    };

    // Parses `text`; malformed input (an unterminated quote, a row with the wrong number of
    // cells) is reported in problems() naming the file and line, and that row is left out.
    static CsvTable parse(const QString &text, const QString &fileName);
    // Reads a file (a resource path such as ":/drivedesk/sim/x.csv" too).
    static CsvTable read(const QString &path);

    const QString &fileName() const { return m_fileName; }
    const QList<Row> &rows() const { return m_rows; }
    const QStringList &problems() const { return m_problems; }
    bool hasColumn(const QString &name) const { return m_columns.contains(name); }
    // The cell of `column` in `row`, trimmed; empty when the column does not exist.
    QString cell(const Row &row, const QString &column) const;

private:
    QString m_fileName;
    QHash<QString, int> m_columns;
    QList<Row> m_rows;
    QStringList m_problems;
};

} // namespace DriveDesk::Sim
