#include "SaveDriveFeature.h"

#include "frame/DriveSession.h"
#include "frame/FileProblem.h"
#include "frame/FrameSupport.h"
#include "frame/NoticeBar.h"
#include "session/UploadRun.h"

#include <QAction>
#include <QDate>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>

namespace DriveDesk {

SaveDriveFeature::SaveDriveFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_action = new QAction(
        tr("Save &Drive to File..."), this);
    m_action->setObjectName(QStringLiteral("saveDriveAction"));
    m_action->setToolTip(tr("Read the drive afresh and save it to a parameter file once "
                                 "every value was read; the window goes on with the drive"));
    connect(m_action, &QAction::triggered, this, &SaveDriveFeature::chooseFile);
    QMenu *file = frame.menu(WindowFrame::Menu::File);
    file->addSeparator();
    file->addAction(m_action);
    // The notice bar's Cancel stops the reading (the frame's stops a scan, which waits for it).
    connect(frame.noticeBar(), &NoticeBar::cancelClicked, this, [this] {
        if (m_upload)
            m_upload->cancel();
    });
}

void SaveDriveFeature::updateActions()
{
    const DriveSession *session = frame().session();
    m_action->setEnabled(session && session->state() == DriveClient::State::Connected
                         && !session->isScanning() && !isSavingDrive());
}

void SaveDriveFeature::chooseFile()
{
    const DriveSession *session = frame().session();
    if (!session || session->state() != DriveClient::State::Connected)
        return;
    const QString name
        = QStringLiteral("drive-%1.json").arg(QDate::currentDate().toString(Qt::ISODate));
    frame().chooseFileToWrite(
        tr("Save Drive to File"), name, {},
        [this](const QString &path) { return saveDriveToFile(path); });
}

bool SaveDriveFeature::saveDriveToFile(const QString &path)
{
    DriveSession *session = frame().session();
    if (!session || session->state() != DriveClient::State::Connected || session->isScanning()
        || m_upload)
        return false;
    // The table may hold a scan stopped halfway or values gone stale: a backup reads the drive
    // afresh, as the command line's upload does.
    auto *upload = new UploadRun(session->client(), session);
    m_upload = upload;
    const QString name = QFileInfo(path).fileName();
    NoticeBar *notice = frame().noticeBar();
    // What the notice said before comes back unless something newer took its place.
    const bool noticeShown = notice->isVisible();
    const NoticeBar::Kind noticeKind = notice->kind();
    const QString noticeText = notice->text();
    connect(upload, &UploadRun::progress, this,
            [notice, name](int value, int maximum, const QString &what) {
                notice->showProgress(tr("Saving the drive to %1: %2")
                                         .arg(name, what),
                                     value, maximum);
            });
    connect(upload, &UploadRun::finished, this,
            [this, notice, upload, path, noticeShown, noticeKind,
             noticeText](const UploadResult &result) {
                upload->deleteLater();
                m_upload.clear(); // done: the next save may start
                if (notice->kind() == NoticeBar::Kind::Progress) {
                    if (!noticeShown)
                        notice->hide();
                    else if (noticeKind == NoticeBar::Kind::Problem)
                        notice->showProblem(noticeText);
                    else if (noticeKind == NoticeBar::Kind::Information)
                        notice->showInformation(noticeText);
                }
                driveRead(result, path);
                frame().updateActions();
            });
    notice->showProgress(tr("Saving the drive to %1: reading the drive...")
                             .arg(name),
                         0, 1000);
    ScanOptions reading;
    reading.metadata = MetadataSource::Cache;
    upload->start(reading);
    frame().updateActions();
    return true;
}

void SaveDriveFeature::driveRead(const UploadResult &result, const QString &path)
{
    if (result.outcome == UploadResult::Outcome::Cancelled) {
        frame().showMessage(
            tr("Save Drive to File cancelled: nothing was saved to %1.")
                .arg(shownPath(path)));
        return;
    }
    const QString title
        = tr("Save Drive to File");
    if (!result.isComplete()) {
        const QString text = tr("The drive was not saved to %1: %2.")
                                 .arg(shownPath(path), result.summary());
        frame().showMessage(text);
        auto *box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok,
                                    frame().frameWidget());
        box->setObjectName(QStringLiteral("uploadRefused"));
        const QStringList details = result.details();
        constexpr int kShown = 8;
        QString missing = tr("Not read:")
                          + QLatin1Char('\n') + details.mid(0, kShown).join(QLatin1Char('\n'));
        if (details.size() > kShown) {
            const int more = int(details.size()) - kShown;
            missing += QLatin1Char('\n')
                       + tr("... and %n more (Show Details...)", nullptr,
                                                     more);
        }
        box->setInformativeText(missing);
        box->setDetailedText(details.join(QLatin1Char('\n')));
        openDialog(box);
        return;
    }
    QString error;
    if (!saveUpload(path, result, &error)) {
        const QString text = tr("Could not save %1: %2. The file on disk is as it was.")
                                 .arg(shownPath(path), error);
        frame().showMessage(text);
        showFileProblem(frame().frameWidget(), title, text);
        return;
    }
    frame().showMessage(tr("Saved %n parameter(s) of the drive to %1.",
                                                    nullptr, result.document.parameterCount())
                            .arg(shownPath(path)));
}

} // namespace DriveDesk
