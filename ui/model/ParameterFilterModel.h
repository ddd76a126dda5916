#pragma once

#include <QSortFilterProxyModel>

#include <optional>

namespace DriveDesk {

// Search and filters over a ParameterModel (through its roles, so it also works with another
// proxy in between). A parameter stays when it matches the search text and every filter that is
// on; a group stays while any of its parameters does. With no filter on, everything stays.
// Sorting keeps groups in the drive's order and compares values by their raw numbers.
class ParameterFilterModel : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit ParameterFilterModel(QObject *parent = nullptr);

    // Case-insensitive, as you type: the id ("ru.3" and "ru.03" both find ru.03), the
    // hexadecimal address, the name or any value as shown; and the parameter that a complete id
    // in any form the command line takes names ("op28", "0x031C", "031Ch").
    void setFilterText(const QString &text);
    QString filterText() const { return m_text; }
    // Settings the user can change where a known value of any set differs from the default
    // (not read-only values, nor those the drive changes itself).
    void setDiffersFromDefaultOnly(bool on);
    bool differsFromDefaultOnly() const { return m_differsOnly; }
    void setFavouritesOnly(bool on);
    bool favouritesOnly() const { return m_favouritesOnly; }
    // Hides parameters that need a higher password level than the one in force.
    void setHideAboveLevel(bool on);
    bool hidesAboveLevel() const { return m_hideAboveLevel; }

    bool isFiltering() const;

    void setSourceModel(QAbstractItemModel *model) override;

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;
    bool lessThan(const QModelIndex &left, const QModelIndex &right) const override;

private:
    void setFlag(bool &flag, bool on);
    // The address the search text names as an id, with the groups the source model has now.
    void updateNamedAddress();

    QString m_text;
    QString m_needle; // m_text, trimmed and lower-case
    std::optional<quint16> m_namedAddress;
    QMetaObject::Connection m_resetConnection; // to the source model's reset
    bool m_differsOnly = false;
    bool m_favouritesOnly = false;
    bool m_hideAboveLevel = false;
};

} // namespace DriveDesk
