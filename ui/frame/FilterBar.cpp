#include "FilterBar.h"

#include <QAction>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLineEdit>

namespace DriveDesk {

FilterBar::FilterBar(QWidget *parent)
    : QWidget(parent)
{
    m_search = new QLineEdit;
    m_search->setObjectName(QStringLiteral("searchField"));
    m_search->setClearButtonEnabled(true);
    m_search->setPlaceholderText(tr("Search every group by id, name or value"));
    m_findAction = new QAction(tr("&Find..."), this);
    m_findAction->setObjectName(QStringLiteral("findAction"));
    m_findAction->setShortcut(QKeySequence::Find);
    m_findAction->setToolTip(tr("Search parameters by id, name or value"));
    connect(m_findAction, &QAction::triggered, this, [this] {
        m_search->setFocus(Qt::ShortcutFocusReason);
        m_search->selectAll();
    });
    m_search->setToolTip(tr("Search every group by id (ru.3), name or value as you type (%1)")
                             .arg(m_findAction->shortcut().toString(QKeySequence::NativeText)));

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_search, 1);

    m_differsAction = addFilter(tr("D&iffers from default"), tr("&Differs from Default"),
                                tr("Only settings whose value differs from the default (not read-only or live values)"));
    m_favouritesAction = addFilter(tr("F&avourites"), tr("F&avourites Only"),
                                   tr("Only the parameters marked with a star"));
    m_hideAboveLevelAction = addFilter(
        tr("Hide above &password level"), tr("&Hide Parameters above Password Level"),
        tr("Hide parameters the password level in force does not open; otherwise they are "
           "greyed out"));
    m_rawAction = addFilter(tr("Ra&w values"), tr("Show &Raw Values"),
                            tr("Show the raw integers the drive holds instead of scaled values "
                               "and plaintexts"));
}

QAction *FilterBar::addFilter(const QString &boxText, const QString &actionText,
                              const QString &toolTip)
{
    auto *box = new QCheckBox(boxText);
    box->setToolTip(toolTip);
    auto *action = new QAction(actionText, this);
    action->setCheckable(true);
    action->setToolTip(toolTip);
    connect(box, &QCheckBox::toggled, action, &QAction::setChecked);
    connect(action, &QAction::toggled, box, &QCheckBox::setChecked);
    layout()->addWidget(box);
    return action;
}

} // namespace DriveDesk
