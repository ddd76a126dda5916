#pragma once

#include <QSortFilterProxyModel>

namespace DriveDesk {

class TrafficModel;

// The monitor's filter over a TrafficModel: a text searched in the meaning, the hex bytes
// (with or without the spaces) and the characters, and "errors only". Keeps the model's order.
class TrafficFilterModel : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit TrafficFilterModel(QObject *parent = nullptr);

    void setTrafficModel(TrafficModel *model);
    TrafficModel *trafficModel() const { return m_traffic; }

    // Case-insensitive; leading and trailing spaces do not count.
    void setFilterText(const QString &text);
    QString filterText() const { return m_text; }
    void setErrorsOnly(bool on);
    bool errorsOnly() const { return m_errorsOnly; }
    bool isFiltering() const { return m_errorsOnly || !m_needle.isEmpty(); }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    TrafficModel *m_traffic = nullptr;
    QString m_text;
    QString m_needle; // m_text trimmed
    QString m_hexNeedle; // m_needle without spaces, upper case, where it is all hex digits
    bool m_errorsOnly = false;
};

} // namespace DriveDesk
