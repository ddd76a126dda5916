#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <QString>

#include <optional>

namespace DriveDesk {

// The first fault of a document: where ("groups[2].parameters[5].min") and what. The place
// finds the line and column; the subject, where the document tells it, is what a user knows
// the place by ("uF.07, set 0") and is what the text names.
struct JsonFault
{
    QString place;
    QString message;
    QString subject;

    bool isEmpty() const { return message.isEmpty(); }
    QString text() const
    {
        const QString &where = subject.isEmpty() ? place : subject;
        return where.isEmpty() ? message : where + QStringLiteral(": ") + message;
    }
};

// Reads the fields of one JSON object of a parameter file, naming the place of a fault
// ("groups[2].parameters[5].min: expected an integer"). The first fault anywhere is kept in
// the error all readers of a document share; after it, reads return defaults, so a caller
// reads every field and checks ok() once.
class JsonObjectReader
{
public:
    JsonObjectReader(QJsonObject object, QString path, JsonFault *error)
        : m_object(std::move(object))
        , m_path(std::move(path))
        , m_error(error)
    { }

    // The reader for element `index` of the array field `key` (which must be an object).
    JsonObjectReader element(const QString &key, const QJsonArray &array, qsizetype index);

    bool ok() const { return m_error->isEmpty(); }
    JsonFault *error() const { return m_error; }
    QString place(const QString &key) const;
    static QString indexed(const QString &place, qsizetype index); // "values[2]"
    void fail(const QString &place, const QString &message);
    bool has(const QString &key) const { return m_object.contains(key); }

    // A missing field is a fault; each read marks the field as known for finish().
    QJsonValue value(const QString &key);
    qint64 integer(const QString &key, qint64 minimum, qint64 maximum);
    std::optional<qint64> checkedInteger(const QJsonValue &json, const QString &place,
                                         qint64 minimum, qint64 maximum);
    QString string(const QString &key);
    bool boolean(const QString &key);
    QJsonArray array(const QString &key);
    QJsonObject object(const QString &key);

    // A field this version does not know is a fault: a misspelt one is not silently dropped.
    void finish();

private:
    QJsonObject m_object;
    QString m_path;
    JsonFault *m_error;
    QSet<QString> m_read;
};

} // namespace DriveDesk
