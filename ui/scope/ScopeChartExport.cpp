// ScopeChart: the chart as a PNG image or a PDF page.
#include "ScopeChart.h"

#include "QCustomPlotInclude.h"

#include "frame/FrameSupport.h"

#include <QDir>
#include <QFileInfo>

namespace DriveDesk {


bool ScopeChart::savePng(const QString &path, QString *error)
{
    if (!checkWritable(path, error))
        return false;
    m_plot->replot(QCustomPlot::rpRefreshHint); // the newest samples, as on screen
    if (m_plot->savePng(path) && QFileInfo(path).size() > 0)
        return true;
    if (error)
        *error = tr("Could not write the image %1.").arg(shownPath(path));
    return false;
}

bool ScopeChart::savePdf(const QString &path, QString *error)
{
    if (!checkWritable(path, error))
        return false;
    m_plot->replot(QCustomPlot::rpRefreshHint);
    const QString title = m_recording ? m_recording->source : QString();
    if (m_plot->savePdf(path, 0, 0, QCP::epAllowCosmetic, QStringLiteral("DriveDesk"), title)
        && QFileInfo(path).size() > 0) {
        return true;
    }
    if (error)
        *error = tr("Could not write the PDF file %1.").arg(shownPath(path));
    return false;
}

// QCustomPlot only says whether saving worked: the likely reasons are checked first.
bool ScopeChart::checkWritable(const QString &path, QString *error) const
{
    QString problem;
    const QFileInfo file(path);
    const QFileInfo folder(file.absolutePath());
    if (path.isEmpty())
        problem = tr("No file name was given.");
    else if (!folder.isDir())
        problem = tr("Cannot save %1: the folder %2 does not exist.")
                      .arg(shownPath(path), shownPath(folder.filePath()));
    else if (!folder.isWritable())
        problem = tr("Cannot save %1: the folder %2 is not writable.")
                      .arg(shownPath(path), shownPath(folder.filePath()));
    else if (file.isDir())
        problem = tr("Cannot save %1: it is a folder.").arg(shownPath(path));
    else if (file.exists() && !file.isWritable())
        problem = tr("Cannot save %1: the file is read-only.").arg(shownPath(path));
    if (problem.isEmpty())
        return true;
    if (error)
        *error = problem;
    return false;
}

} // namespace DriveDesk
