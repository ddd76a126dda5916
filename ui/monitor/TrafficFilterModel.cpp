#include "TrafficFilterModel.h"

#include "TrafficModel.h"

#include <algorithm>

namespace DriveDesk {

namespace {

bool isHexDigit(QChar c)
{
    return (c >= QLatin1Char('0') && c <= QLatin1Char('9'))
        || (c.toUpper() >= QLatin1Char('A') && c.toUpper() <= QLatin1Char('F'));
}

// Whether `hexNeedle` (upper case, no spaces) stands in the bytes starting at a byte boundary.
bool bytesContain(const QByteArray &bytes, const QString &hexNeedle)
{
    const QString hex = QString::fromLatin1(bytes.toHex().toUpper());
    for (qsizetype at = hex.indexOf(hexNeedle); at >= 0; at = hex.indexOf(hexNeedle, at + 1)) {
        if (at % 2 == 0)
            return true;
    }
    return false;
}

} // namespace

TrafficFilterModel::TrafficFilterModel(QObject *parent)
    : QSortFilterProxyModel(parent)
{ }

void TrafficFilterModel::setTrafficModel(TrafficModel *model)
{
    m_traffic = model;
    setSourceModel(model);
}

void TrafficFilterModel::setFilterText(const QString &text)
{
    if (text == m_text)
        return;
    m_text = text;
    m_needle = text.trimmed();
    QString compact = m_needle;
    compact.remove(QLatin1Char(' '));
    const bool allHex
        = !compact.isEmpty() && std::all_of(compact.cbegin(), compact.cend(), isHexDigit);
    m_hexNeedle = allHex ? compact.toUpper() : QString();
    invalidateFilter();
}

void TrafficFilterModel::setErrorsOnly(bool on)
{
    if (on == m_errorsOnly)
        return;
    m_errorsOnly = on;
    invalidateFilter();
}

bool TrafficFilterModel::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    if (!m_traffic || sourceParent.isValid())
        return true;
    const TrafficEntry &entry = m_traffic->entry(sourceRow);
    if (m_errorsOnly && entry.record.kind != TrafficRecord::Kind::Error)
        return false;
    if (m_needle.isEmpty())
        return true;
    if (m_traffic->meaning(sourceRow).contains(m_needle, Qt::CaseInsensitive))
        return true;
    if (!m_hexNeedle.isEmpty() && bytesContain(entry.record.bytes, m_hexNeedle))
        return true;
    return TrafficFormat::characters(entry).contains(m_needle, Qt::CaseInsensitive);
}

} // namespace DriveDesk
