// The telegram monitor's record leaving the window: saved to a file, copied to the clipboard.
#include "TelegramMonitor.h"

#include "TrafficFile.h"
#include "TrafficFilterModel.h"
#include "TrafficModel.h"

#include "frame/FrameSupport.h"

#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QTreeView>

namespace DriveDesk {

namespace {

const QString kSaveDirectoryKey = QStringLiteral("TelegramMonitor/saveDirectory");

} // namespace

bool TelegramMonitor::saveTo(const QString &path, QString *error)
{
    QList<TrafficEntry> entries;
    entries.reserve(m_filter->rowCount());
    for (int row = 0; row < m_filter->rowCount(); ++row) {
        const int source = m_filter->mapToSource(m_filter->index(row, 0)).row();
        m_model->meaning(source);
        entries << m_model->entry(source);
    }
    QString reason;
    if (!TrafficFile::save(path, entries, &reason)) {
        showNotice(reason, true);
        if (error)
            *error = reason;
        return false;
    }
    showNotice(tr("Saved %Ln telegram(s) to %1.", nullptr, int(entries.size()))
                   .arg(QDir::toNativeSeparators(path)),
               false);
    return true;
}

void TelegramMonitor::chooseFileAndSave()
{
    const QString directory = settings().value(kSaveDirectoryKey, QDir::homePath()).toString();
    const QString suggested = QDir(directory).filePath(
        QStringLiteral("telegrams-%1.csv")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss"))));
    const QString csvFilter = tr("CSV files (*.csv)");
    // Opened with open(): no nested event loop while the user chooses.
    auto *dialog = new QFileDialog(this, tr("Save telegrams"), suggested,
                                   csvFilter + QStringLiteral(";;") + tr("Text files (*.txt)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->selectFile(suggested);
    connect(dialog, &QFileDialog::fileSelected, this, [this, dialog, csvFilter](QString path) {
        if (path.isEmpty())
            return;
        if (QFileInfo(path).suffix().isEmpty())
            path += dialog->selectedNameFilter() == csvFilter ? QStringLiteral(".csv")
                                                              : QStringLiteral(".txt");
        settings().setValue(kSaveDirectoryKey, QFileInfo(path).absolutePath());
        QString error;
        if (saveTo(path, &error))
            return;
        auto *box = new QMessageBox(QMessageBox::Warning, tr("Save telegrams"), error,
                                    QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    dialog->open();
}

void TelegramMonitor::copySelection() const
{
    QModelIndexList rows = m_view->selectionModel()->selectedRows();
    if (rows.isEmpty())
        return;
    std::sort(rows.begin(), rows.end(),
              [](const QModelIndex &a, const QModelIndex &b) { return a.row() < b.row(); });
    const bool withCharacters = !m_view->isColumnHidden(TrafficModel::CharactersColumn);
    QStringList lines;
    lines.reserve(rows.size());
    for (const QModelIndex &row : std::as_const(rows)) {
        const int source = m_filter->mapToSource(row).row();
        m_model->meaning(source);
        const TrafficEntry &entry = m_model->entry(source);
        QStringList fields = TrafficFormat::fields(entry, TrafficFormat::Clock::TimeOfDay);
        if (!withCharacters)
            fields.removeAt(TrafficFormat::Characters);
        lines << TrafficFormat::tabSeparated(fields);
    }
    QGuiApplication::clipboard()->setText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n'));
}

} // namespace DriveDesk
