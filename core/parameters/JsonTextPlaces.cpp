#include "JsonTextPlaces.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>
#include <QStringList>

namespace DriveDesk::JsonTextPlaces {

namespace {

// Walks valid JSON text. `Visitor` decides per member or element whether to descend.
class Walker
{
public:
    explicit Walker(QByteArrayView json)
        : m_json(json)
    { }

    qsizetype position() const { return m_at; }
    void skipSpace()
    {
        while (m_at < m_json.size()
               && (m_json[m_at] == ' ' || m_json[m_at] == '\t' || m_json[m_at] == '\n'
                   || m_json[m_at] == '\r'))
            ++m_at;
    }
    char peek() const { return m_at < m_json.size() ? m_json[m_at] : '\0'; }
    void take() { ++m_at; }

    // The decoded text of the string at the current position; moves past it.
    QString string()
    {
        const qsizetype start = m_at;
        bool escaped = false;
        ++m_at; // the opening quote
        while (m_at < m_json.size() && m_json[m_at] != '"') {
            if (m_json[m_at] == '\\') {
                escaped = true;
                ++m_at;
            }
            ++m_at;
        }
        ++m_at; // the closing quote
        const QByteArrayView text = m_json.sliced(start, qMin(m_at, m_json.size()) - start);
        if (!escaped)
            return QString::fromUtf8(text.sliced(1, qMax<qsizetype>(0, text.size() - 2)));
        const QByteArray array = "[" + text.toByteArray() + "]";
        return QJsonDocument::fromJson(array).array().at(0).toString();
    }

    void skipValue()
    {
        skipSpace();
        const char c = peek();
        if (c == '"') {
            string();
        } else if (c == '{' || c == '[') {
            int depth = 0;
            do {
                const char d = peek();
                if (d == '"') {
                    string();
                    continue;
                }
                if (d == '{' || d == '[')
                    ++depth;
                else if (d == '}' || d == ']')
                    --depth;
                take();
            } while (depth > 0 && m_at < m_json.size());
        } else {
            while (m_at < m_json.size() && !QByteArrayView(",]} \t\r\n").contains(peek()))
                take();
        }
    }

private:
    QByteArrayView m_json;
    qsizetype m_at = 0;
};

QString joined(const QStringList &segments)
{
    QString path;
    for (const QString &segment : segments) {
        if (!path.isEmpty() && !segment.startsWith(QLatin1Char('[')))
            path += QLatin1Char('.');
        path += segment;
    }
    return path;
}

bool findDuplicate(Walker &walker, QStringList &path, std::optional<Place> &found)
{
    walker.skipSpace();
    const char c = walker.peek();
    if (c == '{') {
        walker.take();
        QSet<QString> keys;
        for (;;) {
            walker.skipSpace();
            if (walker.peek() != '"') { // '}' of an empty object
                walker.take();
                return false;
            }
            const qsizetype at = walker.position();
            const QString key = walker.string();
            path.append(key);
            if (keys.contains(key)) {
                found = Place { joined(path), at };
                return true;
            }
            keys.insert(key);
            walker.skipSpace();
            walker.take(); // ':'
            if (findDuplicate(walker, path, found))
                return true;
            path.removeLast();
            walker.skipSpace();
            const char next = walker.peek();
            walker.take();
            if (next != ',')
                return false;
        }
    }
    if (c == '[') {
        walker.take();
        for (qsizetype index = 0;; ++index) {
            walker.skipSpace();
            if (walker.peek() == ']') {
                walker.take();
                return false;
            }
            path.append(QStringLiteral("[%1]").arg(index));
            if (findDuplicate(walker, path, found))
                return true;
            path.removeLast();
            walker.skipSpace();
            const char next = walker.peek();
            walker.take();
            if (next != ',')
                return false;
        }
    }
    walker.skipValue();
    return false;
}

// Whether `path` is `prefix` or lies inside it.
bool within(const QString &path, const QString &prefix)
{
    if (!path.startsWith(prefix))
        return false;
    if (path.size() == prefix.size())
        return true;
    const QChar next = path.at(prefix.size());
    return next == QLatin1Char('.') || next == QLatin1Char('[');
}

// Descends towards `target`; returns the offset of the deepest place on its way.
qsizetype descend(Walker &walker, const QString &here, const QString &target, qsizetype offset)
{
    if (here == target)
        return offset;
    walker.skipSpace();
    const char c = walker.peek();
    if (c == '{') {
        walker.take();
        for (;;) {
            walker.skipSpace();
            if (walker.peek() != '"')
                return offset;
            const qsizetype at = walker.position();
            const QString key = walker.string();
            const QString path = here.isEmpty() ? key : here + QLatin1Char('.') + key;
            walker.skipSpace();
            walker.take(); // ':'
            if (within(target, path))
                return descend(walker, path, target, at);
            walker.skipValue();
            walker.skipSpace();
            if (walker.peek() != ',')
                return offset;
            walker.take();
        }
    }
    if (c == '[') {
        walker.take();
        for (qsizetype index = 0;; ++index) {
            walker.skipSpace();
            if (walker.peek() == ']')
                return offset;
            const QString path = here + QStringLiteral("[%1]").arg(index);
            if (within(target, path))
                return descend(walker, path, target, walker.position());
            walker.skipValue();
            walker.skipSpace();
            if (walker.peek() != ',')
                return offset;
            walker.take();
        }
    }
    return offset;
}

} // namespace

std::optional<Place> firstDuplicateKey(QByteArrayView json)
{
    Walker walker(json);
    QStringList path;
    std::optional<Place> found;
    findDuplicate(walker, path, found);
    return found;
}

qsizetype offsetOf(QByteArrayView json, const QString &path)
{
    Walker walker(json);
    walker.skipSpace();
    return descend(walker, QString(), path, walker.position());
}

LineColumn lineColumn(QByteArrayView json, qsizetype offset)
{
    const QByteArrayView before = json.first(qBound<qsizetype>(0, offset, json.size()));
    const qsizetype lineStart = before.lastIndexOf('\n') + 1;
    return LineColumn { before.count('\n') + 1, before.size() - lineStart + 1 };
}

} // namespace DriveDesk::JsonTextPlaces
