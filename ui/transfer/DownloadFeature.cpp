#include "DownloadFeature.h"

#include "DownloadDialog.h"

#include "frame/DriveSession.h"
#include "frame/FileProblem.h"
#include "frame/FrameSupport.h"
#include "frame/RunJournal.h"
#include "parameters/ParameterDocument.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>

namespace DriveDesk {

DownloadFeature::DownloadFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_action = new QAction(themedIcon("document-send", QStyle::SP_ArrowUp),
                           tr("Down&load File to Drive..."), this);
    m_action->setObjectName(QStringLiteral("downloadAction"));
    m_action->setToolTip(tr("Write a parameter file's values to the drive, after a last look "
                            "at what differs"));
    connect(m_action, &QAction::triggered, this, [this] {
        this->frame().chooseParameterFile(tr("Download File to Drive"),
                                          [this](const QString &path) { downloadFile(path); });
    });
    QMenu *drive = frame.menu(WindowFrame::Menu::Drive);
    drive->addSeparator();
    drive->addAction(m_action);
}

void DownloadFeature::attach(DriveSession *session)
{
    Q_UNUSED(session)
    // A download belongs to the connection it began on; its run sees the client go.
    updateActions();
}

void DownloadFeature::updateActions()
{
    m_action->setEnabled(frame().isReady() && !isBusy());
}

DownloadDialog *DownloadFeature::dialog() const
{
    return m_dialog;
}

bool DownloadFeature::isBusy() const
{
    return m_dialog && m_dialog->isVisible();
}

void DownloadFeature::downloadFile(const QString &path)
{
    QString error;
    const std::optional<DriveDescription> file = ParameterDocument::load(path, &error);
    if (!file) {
        const QString text = tr("Nothing was written: %1").arg(error);
        frame().showMessage(text);
        showFileProblem(frame().frameWidget(), tr("Download File to Drive"), text);
        return;
    }
    download(*file, {}, tr("the values of %1").arg(QDir::toNativeSeparators(path)),
             tr("download of %1").arg(QFileInfo(path).fileName()));
}

void DownloadFeature::downloadSelection(const DriveDescription &selection, const QString &what,
                                        const QString &journalJob)
{
    DownloadOptions options;
    options.selection = true;
    options.journalJob = journalJob;
    const QString values = what.isEmpty() ? tr("the values chosen in the compare window") : what;
    download(selection, options, values,
             journalJob.isEmpty() ? tr("download of %1").arg(values) : journalJob);
}

void DownloadFeature::download(const DriveDescription &file, const DownloadOptions &options,
                               const QString &source, const QString &job)
{
    DriveSession *session = frame().session();
    if (!frame().isReady() || !session || isBusy()) {
        frame().showMessage(isBusy() ? tr("A download is on its way already.")
                                     : tr("Nothing was written: no drive is connected."));
        return;
    }
    auto *run = new DownloadRun(session->client(), session->settings().protocol, file);
    run->setOptions(options);
    if (m_journaled && m_journaled())
        run->setJournal(RunJournal::attach(run, job));
    m_dialog = new DownloadDialog(run, source, frame().frameWidget());
    connect(m_dialog, &DownloadDialog::wrote, this, [this] {
        // The table shows what the drive holds now, read again.
        if (frame().isReady())
            frame().session()->readValuesAgain();
        frame().showMessage(tr("Download finished; the values are read again."));
    });
    connect(m_dialog, &QDialog::finished, this, [this] { frame().updateActions(); });
    m_dialog->setAttribute(Qt::WA_DeleteOnClose);
    m_dialog->show();
    ScanOptions reading;
    reading.metadata = MetadataSource::Cache; // what the window read a moment ago, as a rule
    run->start(reading);
    frame().updateActions();
}

} // namespace DriveDesk
