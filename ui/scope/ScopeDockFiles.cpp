// The scope dock's files: recordings opened and recorded to, CSV, PNG and PDF.
#include "ScopeDock.h"

#include "ScopeChart.h"

#include "frame/WindowFeature.h"
#include "scope/ScopeFileFormat.h"
#include "scope/ScopeFileWriter.h"
#include "scope/ScopeRecording.h"

#include <QAction>
#include <QDateTime>
#include <QFile>
#include <QMessageBox>
#include <QPushButton>

#include <filesystem>

namespace DriveDesk {

namespace {

QString stampedName(const QString &suffix)
{
    return QStringLiteral("scope-%1.%2")
        .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")), suffix);
}

} // namespace

QString ScopeDock::recordingFilter()
{
    return tr("DriveDesk scope recordings (*.%1)").arg(QLatin1String(ScopeFileFormat::kSuffix));
}

void ScopeDock::chooseRecordingToOpen()
{
    if (isRecording())
        return showStatus(tr("Stop the recording before opening another."), true);
    confirmReplacing(tr("Open Scope Recording"),
                     tr("The recording shown is not saved. The recording opened replaces it."),
                     [this] {
                         m_frame.chooseFileToRead(tr("Open Scope Recording"), recordingFilter(),
                                                  [this](const QString &path) {
                                                      QString error;
                                                      if (!openRecording(path, &error))
                                                          showStatus(error, true);
                                                  });
                     });
}

void ScopeDock::chooseRecordingFile(bool on)
{
    if (!on)
        return setRecordFile({});
    m_toFileAction->setChecked(false); // until a file is chosen
    m_frame.chooseFileToWrite(tr("Record to File"),
                              stampedName(QLatin1String(ScopeFileFormat::kSuffix)),
                              recordingFilter(),
                              [this](const QString &path) {
                                  setRecordFile(path);
                                  return true;
                              });
}

void ScopeDock::setRecordFile(const QString &path)
{
    m_recordFile = path;
    m_toFileAction->setChecked(!path.isEmpty());
    showStatus(path.isEmpty() ? tr("Recordings stay in memory.")
                              : tr("The next recording also goes into %1.").arg(path));
}

void ScopeDock::chooseRecordingToSave()
{
    if (m_recording->buffer.count() == 0)
        return showStatus(tr("There is nothing recorded to save."), true);
    if (isRecording())
        return showStatus(tr("Stop the recording before saving it, or use Record to File."), true);
    saveRecordingThen({});
}

void ScopeDock::saveRecordingThen(const std::function<void()> &saved)
{
    m_frame.chooseFileToWrite(tr("Save Scope Recording"),
                              stampedName(QLatin1String(ScopeFileFormat::kSuffix)),
                              recordingFilter(), [this, saved](const QString &path) {
                                  QString error;
                                  if (!saveRecording(path, &error)) {
                                      showStatus(error, true);
                                      return false;
                                  }
                                  showStatus(tr("Saved to %1.").arg(path));
                                  if (saved)
                                      saved();
                                  return true;
                              });
}

bool ScopeDock::saveRecording(const QString &path, QString *error)
{
    // Written beside the target and renamed at the end: a failure leaves no half file, and an
    // older file of that name stays until the new one is complete.
    const QString partial = path + QStringLiteral(".part");
    ScopeFileWriter writer;
    const SampleStore &samples = m_recording->buffer.samples();
    const bool written = writer.open(partial, ScopeFileHeader::of(*m_recording), error)
                         && writer.append(samples, 0, samples.count(), error)
                         && writer.close(error);
    if (!written) {
        QFile::remove(partial);
        return false;
    }
    // Replaces an older file in one step (std::filesystem::rename does, where QFile's refuses).
    std::error_code failed;
    std::filesystem::rename(std::filesystem::path(partial.toStdU16String()),
                            std::filesystem::path(path.toStdU16String()), failed);
    if (failed) {
        QFile::remove(partial);
        if (error)
            *error = tr("Cannot save %1: %2").arg(path, QString::fromStdString(failed.message()));
        return false;
    }
    m_unsaved = false;
    return true;
}

void ScopeDock::chooseCsv(bool visibleOnly)
{
    if (m_recording->buffer.count() == 0)
        return showStatus(tr("There is nothing recorded to export."), true);
    m_frame.chooseFileToWrite(visibleOnly ? tr("Export Visible Range as CSV")
                                          : tr("Export All as CSV"),
                              stampedName(QStringLiteral("csv")), tr("CSV files (*.csv)"),
                              [this, visibleOnly](const QString &path) {
                                  QString error;
                                  if (!exportCsv(path, visibleOnly, &error)) {
                                      showStatus(error, true);
                                      return false;
                                  }
                                  showStatus(tr("Exported to %1.").arg(path));
                                  return true;
                              });
}

bool ScopeDock::hasUnsavedRecording() const
{
    return m_unsaved && m_recording->buffer.count() > 0;
}

void ScopeDock::settleBeforeClosing(const std::function<void()> &proceed)
{
    confirmReplacing(tr("Close DriveDesk"),
                     tr("The scope recording shown is not saved. Closing DriveDesk loses it."),
                     proceed);
}

void ScopeDock::confirmReplacing(const QString &title, const QString &text,
                                 const std::function<void()> &proceed)
{
    if (!hasUnsavedRecording())
        return proceed();
    auto *box = new QMessageBox(QMessageBox::Question, title, text,
                                QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                this);
    box->setObjectName(QStringLiteral("scopeReplaceQuestion"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setInformativeText(tr("Save it first?"));
    box->button(QMessageBox::Save)->setText(tr("&Save..."));
    box->setDefaultButton(QMessageBox::Cancel);
    connect(box, &QMessageBox::finished, this, [this, box, proceed] {
        switch (box->standardButton(box->clickedButton())) {
        case QMessageBox::Save:
            saveRecordingThen(proceed);
            break;
        case QMessageBox::Discard:
            proceed();
            break;
        default:
            break;
        }
    });
    box->open();
}

void ScopeDock::chooseImage(bool pdf)
{
    const QString suffix = pdf ? QStringLiteral("pdf") : QStringLiteral("png");
    m_frame.chooseFileToWrite(pdf ? tr("Export Chart as PDF") : tr("Export Chart as PNG"),
                              stampedName(suffix),
                              pdf ? tr("PDF files (*.pdf)") : tr("PNG images (*.png)"),
                              [this, pdf](const QString &path) {
                                  QString error;
                                  const bool saved = pdf ? m_chart->savePdf(path, &error)
                                                         : m_chart->savePng(path, &error);
                                  if (saved)
                                      showStatus(tr("Exported to %1.").arg(path));
                                  else
                                      showStatus(error, true);
                                  return saved;
                              });
}

} // namespace DriveDesk
