#pragma once

#include <QWidget>

class QAction;
class QLineEdit;

namespace DriveDesk {

// The row above the parameter table: the search field and the filter check boxes, each check
// box in step with a checkable action for the menus. It only says what the user chose; the
// ParameterBrowser applies it.
class FilterBar : public QWidget
{
    Q_OBJECT
public:
    explicit FilterBar(QWidget *parent = nullptr);

    QLineEdit *searchField() const { return m_search; }
    QAction *findAction() const { return m_findAction; } // focuses the search field
    QAction *differsAction() const { return m_differsAction; }
    QAction *favouritesAction() const { return m_favouritesAction; }
    QAction *hideAboveLevelAction() const { return m_hideAboveLevelAction; }
    QAction *rawValuesAction() const { return m_rawAction; }

private:
    QAction *addFilter(const QString &boxText, const QString &actionText, const QString &toolTip);

    QLineEdit *m_search = nullptr;
    QAction *m_findAction = nullptr;
    QAction *m_differsAction = nullptr;
    QAction *m_favouritesAction = nullptr;
    QAction *m_hideAboveLevelAction = nullptr;
    QAction *m_rawAction = nullptr;
};

} // namespace DriveDesk
