#pragma once

#include <QByteArrayView>
#include <QString>

#include <optional>

namespace DriveDesk {

// Where things stand in the text of a JSON document that QJsonDocument has already accepted:
// QJsonObject keeps one value per key and no positions, so a parameter file's reader looks
// here for keys given twice and for the line and column of a field it refuses.
// Places are written as JsonObjectReader writes them: "groups[2].parameters[5].min".
namespace JsonTextPlaces {

struct Place
{
    QString path;
    qsizetype offset = 0; // byte offset of the key (object member) or value (array element)
};

// The first key that appears a second time in one object, at its second appearance.
std::optional<Place> firstDuplicateKey(QByteArrayView json);

// The offset of the field or element at `path`; where it does not exist (a missing field), of
// the nearest enclosing one that does.
qsizetype offsetOf(QByteArrayView json, const QString &path);

// 1-based line and column (in bytes) of `offset`.
struct LineColumn
{
    qsizetype line = 1;
    qsizetype column = 1;
};
LineColumn lineColumn(QByteArrayView json, qsizetype offset);

} // namespace JsonTextPlaces

} // namespace DriveDesk
