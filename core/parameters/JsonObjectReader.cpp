#include "JsonObjectReader.h"

#include "ParameterDocument.h"

#include <cmath>

namespace DriveDesk {

JsonObjectReader JsonObjectReader::element(const QString &key, const QJsonArray &array,
                                           qsizetype index)
{
    const QString where = indexed(place(key), index);
    const QJsonValue json = array.at(index);
    if (!json.isObject())
        fail(where, ParameterDocument::tr("expected an object"));
    return JsonObjectReader(json.toObject(), where, m_error);
}

QString JsonObjectReader::place(const QString &key) const
{
    return m_path.isEmpty() ? key : m_path + QLatin1Char('.') + key;
}

QString JsonObjectReader::indexed(const QString &place, qsizetype index)
{
    return QStringLiteral("%1[%2]").arg(place).arg(index);
}

void JsonObjectReader::fail(const QString &place, const QString &message)
{
    if (m_error->isEmpty())
        *m_error = JsonFault { place, message, {} };
}

QJsonValue JsonObjectReader::value(const QString &key)
{
    m_read.insert(key);
    if (!m_object.contains(key)) {
        fail(place(key), ParameterDocument::tr("missing"));
        return {};
    }
    return m_object.value(key);
}

qint64 JsonObjectReader::integer(const QString &key, qint64 minimum, qint64 maximum)
{
    const QJsonValue json = value(key);
    if (!ok())
        return 0;
    return checkedInteger(json, place(key), minimum, maximum).value_or(0);
}

std::optional<qint64> JsonObjectReader::checkedInteger(const QJsonValue &json, const QString &where,
                                                       qint64 minimum, qint64 maximum)
{
    const double number = json.toDouble();
    if (!json.isDouble() || !std::isfinite(number) || std::trunc(number) != number
        || std::fabs(number) > 9.0e18) {
        fail(where, ParameterDocument::tr("expected an integer"));
        return std::nullopt;
    }
    const qint64 integer = json.toInteger();
    if (integer < minimum || integer > maximum) {
        fail(where,
             ParameterDocument::tr("%1 is outside %2..%3").arg(integer).arg(minimum).arg(maximum));
        return std::nullopt;
    }
    return integer;
}

QString JsonObjectReader::string(const QString &key)
{
    const QJsonValue json = value(key);
    if (ok() && !json.isString())
        fail(place(key), ParameterDocument::tr("expected a string"));
    return json.toString();
}

bool JsonObjectReader::boolean(const QString &key)
{
    const QJsonValue json = value(key);
    if (ok() && !json.isBool())
        fail(place(key), ParameterDocument::tr("expected true or false"));
    return json.toBool();
}

QJsonArray JsonObjectReader::array(const QString &key)
{
    const QJsonValue json = value(key);
    if (ok() && !json.isArray())
        fail(place(key), ParameterDocument::tr("expected an array"));
    return json.toArray();
}

QJsonObject JsonObjectReader::object(const QString &key)
{
    const QJsonValue json = value(key);
    if (ok() && !json.isObject())
        fail(place(key), ParameterDocument::tr("expected an object"));
    return json.toObject();
}

void JsonObjectReader::finish()
{
    for (auto it = m_object.constBegin(); it != m_object.constEnd(); ++it) {
        if (!m_read.contains(it.key()))
            fail(place(it.key()), ParameterDocument::tr("unknown field"));
    }
}

} // namespace DriveDesk
