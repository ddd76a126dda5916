#include "PlantReportDialog.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace DriveDesk {

PlantReportDialog::PlantReportDialog(const QString &title, const QString &summary,
                                     const QList<PlantDrive> &drives, bool confirm, QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("plantReportDialog"));
    setWindowTitle(title);
    m_summary = new QLabel(summary);
    m_summary->setWordWrap(true);
    m_list = new QTreeWidget;
    m_list->setObjectName(QStringLiteral("plantReportList"));
    m_list->setHeaderLabels({ tr("Drive"), tr("Result") });
    m_list->header()->setStretchLastSection(true);
    for (const PlantDrive &drive : drives) {
        const QString result = drive.reason.isEmpty()
            ? PlantDrive::outcomeText(drive.outcome)
            : tr("%1: %2").arg(PlantDrive::outcomeText(drive.outcome), drive.reason);
        auto *item = new QTreeWidgetItem(m_list, { drive.name(), result });
        item->setToolTip(1, result);
        // The plan or the report of DownloadRun, a line a value.
        for (const QString &line : drive.details.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
            new QTreeWidgetItem(item, { QString(), line.trimmed() });
    }
    m_list->expandAll();
    m_list->resizeColumnToContents(0);
    m_buttons = new QDialogButtonBox(confirm ? QDialogButtonBox::Cancel : QDialogButtonBox::Close);
    if (confirm) {
        QPushButton *write
            = m_buttons->addButton(tr("&Write to the Drives"), QDialogButtonBox::AcceptRole);
        write->setObjectName(QStringLiteral("plantWriteButton"));
    }
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_list, 1);
    layout->addWidget(m_buttons);
    resize(760, 480);
}

QString PlantReportDialog::summary() const
{
    return m_summary->text();
}

} // namespace DriveDesk
