#pragma once

#include "plant/PlantRun.h"

#include <QDialog>

class QDialogButtonBox;
class QLabel;
class QTreeWidget;

namespace DriveDesk {

// Every drive of a plant job with its result and what it says in detail: Download All's last
// look (what each drive would get, with Write to go on) and its combined report. Never modal.
class PlantReportDialog : public QDialog
{
    Q_OBJECT
public:
    // `confirm`: a last look, accepted with Write; otherwise a report to close.
    PlantReportDialog(const QString &title, const QString &summary, const QList<PlantDrive> &drives,
                      bool confirm, QWidget *parent = nullptr);

    QTreeWidget *list() const { return m_list; }
    QString summary() const;

private:
    QLabel *m_summary = nullptr;
    QTreeWidget *m_list = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace DriveDesk
