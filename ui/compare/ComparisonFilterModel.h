#pragma once

#include "model/ParameterFilterModel.h"

#include "parameters/ParameterComparison.h"

namespace DriveDesk {

// The compare view's filters over a ComparisonModel: the parameter table's search
// (ParameterFilterModel, unchanged: the same ids, addresses, names and values match), the states
// shown, one group, and the chosen rows only.
class ComparisonFilterModel : public ParameterFilterModel
{
    Q_OBJECT
public:
    explicit ComparisonFilterModel(QObject *parent = nullptr);

    // Every state but NotASetting is shown at first.
    void setStateShown(ComparisonRow::State state, bool shown);
    bool isStateShown(ComparisonRow::State state) const { return m_states & bit(state); }
    // A group's id ("oP"); empty: every group.
    void setGroup(const QString &groupId);
    QString group() const { return m_group; }
    void setChosenOnly(bool on);
    bool chosenOnly() const { return m_chosenOnly; }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    static quint8 bit(ComparisonRow::State state) { return quint8(1u << int(state)); }

    // A bit per state shown.
    quint8 m_states = quint8(0xFF & ~bit(ComparisonRow::State::NotASetting));
    QString m_group;
    bool m_chosenOnly = false;
};

} // namespace DriveDesk
