// MainWindow: what the session's way from connecting to a read drive shows in the notice bar,
// the status bar and the title, and what a lost link or a silent drive shows.
#include "MainWindow.h"

#include "frame/DriveSession.h"
#include "frame/NoticeBar.h"
#include "frame/ParameterBrowser.h"
#include "RecentConnections.h"

#include "model/ParameterModel.h"
#include "parameters/DriveIdentity.h"

#include <QDateTime>
#include <QLabel>

namespace DriveDesk {

void MainWindow::onStateChanged(DriveClient::State state)
{
    QString text;
    switch (state) {
    case DriveClient::State::Disconnected:
        text = tr("Not connected");
        break;
    case DriveClient::State::Connecting:
        text = tr("Connecting...");
        break;
    case DriveClient::State::Connected:
        text = m_session->isDriveSilent()
                   ? tr("Connected: %1; the drive is not answering")
                         .arg(RecentConnections::describe(m_session->settings()))
                   : tr("Connected: %1").arg(RecentConnections::describe(m_session->settings()));
        break;
    case DriveClient::State::Lost:
        text = tr("Connection lost");
        break;
    }
    m_stateLabel->setText(text);
    updateActions();
    // connectTo() waits for the old link to close; the session may not go from inside its own
    // signal.
    if (m_nextSettings && state != DriveClient::State::Connected
        && state != DriveClient::State::Connecting)
        QMetaObject::invokeMethod(this, &MainWindow::openNextSession, Qt::QueuedConnection);
}

void MainWindow::onScanProgress(int value, int maximum, const QString &text)
{
    m_notice->showProgress(text.isEmpty() ? tr("Reading the drive...")
                                          : tr("Reading the drive: %1").arg(text),
                           value, maximum);
}

void MainWindow::onDescribed(const DriveDescription &drive)
{
    m_metadataLabel->setVisible(drive.metadataFromCache);
    if (!drive.warnings.isEmpty())
        m_notice->showInformation(drive.warnings.join(QLatin1Char('\n')));
    m_favourites.restore(drive, &m_session->settings());
    const QString identity = DriveIdentity::summary(drive);
    const QString name
        = identity.isEmpty() ? RecentConnections::describe(m_session->settings()) : identity;
    setWindowTitle(tr("%1 - DriveDesk").arg(name));
}

void MainWindow::onScanFinished(const QString &problem)
{
    m_browser->setEmptyText(problem.isEmpty()
                                ? tr("The drive reported no parameters.")
                                : tr("Nothing was read from the drive: %1.").arg(problem));
    int parameters = 0;
    for (int group = 0; group < m_model->rowCount(); ++group)
        parameters += m_model->rowCount(m_model->index(group, 0));
    if (problem.isEmpty()) {
        m_notice->hide();
        // One sentence per count: the plural of each is its own.
        showMessage(tr("Read %n parameter(s).", nullptr, parameters) + QLatin1Char(' ')
                    + tr("The drive has %n group(s).", nullptr, m_model->rowCount()));
    } else if (m_model->rowCount() == 0) {
        m_notice->showInformation(
            tr("Nothing was read: %1. Press Refresh (%2) to read the drive.")
                .arg(problem, m_refreshAction->shortcut().toString(QKeySequence::NativeText)));
    } else {
        const QString shown = tr("the table shows the %n parameter(s) read", nullptr, parameters);
        m_notice->showProblem(tr("The drive was read only in part (%1): %2. Read it again with "
                                 "Drive > Read Metadata Again.")
                                  .arg(problem, shown));
        showMessage(tr("Incomplete: %1").arg(shown));
    }
    updateActions();
    emit driveRead();
}

void MainWindow::onLinkLost(const QString &reason)
{
    const QString text = tr("The connection to the drive was lost: %1. What was read stays "
                            "shown; editing is off until the drive is reconnected.")
                             .arg(reason);
    m_notice->showProblem(text);
    showMessage(tr("Connection lost: %1").arg(reason));
    updateActions();
}

void MainWindow::onDriveSilentChanged(bool silent)
{
    if (silent) {
        const QDateTime now = QDateTime::currentDateTime();
        m_model->state()->setStaleSince(now.toMSecsSinceEpoch());
        m_silenceNotice
            = tr("The drive is not answering: the connection to %1 is open, but no valid answer "
                 "came from the drive since %2 (nothing at all, or only what cannot be an "
                 "answer). The values shown are the last read and are marked stale. This clears "
                 "by itself when the drive answers again.")
                  .arg(RecentConnections::describe(m_session->settings()),
                       now.toString(QStringLiteral("HH:mm:ss")));
        m_notice->showProblem(m_silenceNotice);
        showMessage(tr("The drive is not answering"));
    } else {
        m_model->state()->setStaleSince(0);
        if (!m_silenceNotice.isEmpty() && m_notice->isVisible()
            && m_notice->text() == m_silenceNotice) {
            m_notice->hide();
            if (m_session && m_session->state() == DriveClient::State::Connected)
                showMessage(tr("The drive answers again."));
        }
        m_silenceNotice.clear();
    }
    onStateChanged(m_session ? m_session->state() : DriveClient::State::Disconnected);
}

void MainWindow::onConnectionFailed(const QString &reason)
{
    m_browser->setEmptyText(tr("Could not connect: %1").arg(reason));
    const QString target = RecentConnections::describe(m_session->settings());
    // What an earlier connection read stays shown.
    m_notice->showProblem(m_model->rowCount() > 0
                              ? tr("Could not connect to %1: %2. What was shown before stays.")
                                    .arg(target, reason)
                              : tr("Could not connect to %1: %2").arg(target, reason));
    showMessage(tr("Could not connect: %1").arg(reason));
    updateActions();
}

} // namespace DriveDesk
