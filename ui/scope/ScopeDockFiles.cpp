// The scope dock's files: recordings opened and recorded to, CSV, PNG and PDF.
#include "ScopeDock.h"

#include "ScopeChart.h"

#include "main/WindowFeature.h"
#include "scope/ScopeFileFormat.h"
#include "scope/ScopeRecording.h"

#include <QAction>
#include <QDateTime>

namespace DriveDesk {

namespace {

QString recordingFilter()
{
    return ScopeDock::tr("DriveDesk scope recordings (*.%1)").arg(QLatin1String(ScopeFileFormat::kSuffix));
}

QString stampedName(const QString &suffix)
{
    return QStringLiteral("scope-%1.%2")
        .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")), suffix);
}

} // namespace

void ScopeDock::chooseRecordingToOpen()
{
    if (isRecording())
        return showStatus(tr("Stop the recording before opening another."), true);
    m_frame.chooseFileToRead(tr("Open Scope Recording"), recordingFilter(),
                             [this](const QString &path) {
                                 QString error;
                                 if (!openRecording(path, &error))
                                     showStatus(error, true);
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
                              [this](const QString &path) { setRecordFile(path); });
}

void ScopeDock::setRecordFile(const QString &path)
{
    m_recordFile = path;
    m_toFileAction->setChecked(!path.isEmpty());
    showStatus(path.isEmpty() ? tr("Recordings stay in memory.")
                              : tr("The next recording also goes into %1.").arg(path));
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
                                  if (!exportCsv(path, visibleOnly, &error))
                                      return showStatus(error, true);
                                  showStatus(tr("Exported to %1.").arg(path));
                              });
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
                                  if (!saved)
                                      return showStatus(error, true);
                                  showStatus(tr("Exported to %1.").arg(path));
                              });
}

} // namespace DriveDesk
