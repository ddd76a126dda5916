#include "AccessFeature.h"

#include "AccessController.h"
#include "PasswordDialog.h"

#include "frame/DriveSession.h"
#include "frame/FrameSupport.h"
#include "frame/ParameterBrowser.h"
#include "frame/ParameterView.h"

#include <QAction>
#include <QLabel>
#include <QMenu>
#include <QToolBar>

namespace DriveDesk {

AccessFeature::AccessFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_passwordAction = new QAction(themedIcon("dialog-password", QStyle::SP_DialogYesButton),
                                   tr("&Password..."), this);
    m_passwordAction->setObjectName(QStringLiteral("passwordAction"));
    m_passwordAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    m_passwordAction->setToolTip(tr("Enter a password to open a higher password level"));
    connect(m_passwordAction, &QAction::triggered, this, &AccessFeature::enterPassword);
    QMenu *edit = frame.menu(WindowFrame::Menu::Edit);
    edit->addSeparator();
    edit->addAction(m_passwordAction);
    m_passwordAction->setPriority(QAction::LowPriority); // icon only: the toolbar must fit
    QToolBar *bar = frame.toolBar();
    bar->addSeparator();
    bar->addAction(m_passwordAction);

    // Editing the password parameter in the table asks for a password here, where a refusal
    // is explained and nothing enters the undo history.
    connect(frame.browser()->view(), &ParameterView::passwordRequested, this,
            &AccessFeature::enterPassword);

    m_levelLabel = new QLabel;
    m_levelLabel->setObjectName(QStringLiteral("passwordLevel"));
    m_levelLabel->setToolTip(tr("The password level in force on the drive (ud.01)"));
    frame.addStatusWidget(m_levelLabel);
}

void AccessFeature::attach(DriveSession *session)
{
    m_levelLabel->clear();
    // It holds the old session's client, which goes after this.
    delete m_access;
    m_access = nullptr;
    if (!session)
        return;
    m_access = new AccessController(session->client(), frame().state(), this);
    connect(m_access, &AccessController::message, this,
            [this](const QString &text) { frame().showMessage(text); });
    connect(m_access, &AccessController::levelRaised, this, &AccessFeature::levelRaised);
    connect(session, &DriveSession::ready, m_access, &AccessController::readLevel);
    connect(m_access, &AccessController::levelChanged, this,
            [this](PasswordLevel level) {
                m_levelLabel->setText(tr("Password level: %1")
                                          .arg(passwordLevelName(level)));
            });
}

void AccessFeature::updateActions()
{
    m_passwordAction->setEnabled(frame().isReady());
}

void AccessFeature::enterPassword()
{
    if (!frame().isReady() || !m_access)
        return;
    const AccessController *access = m_access;
    auto *dialog = new PasswordDialog(frame().frameWidget());
    dialog->setLevel(access->isLevelKnown() ? std::optional<PasswordLevel>(access->level())
                                            : std::nullopt);
    connect(dialog, &PasswordDialog::passwordEntered, this, [this, dialog](int password) {
        if (!frame().isReady() || !m_access) {
            dialog->passwordRefused(tr("not connected"));
            return;
        }
        m_access->enterPassword(password);
    });
    // The session's answer reaches only a dialog that is waiting for one.
    connect(access, &AccessController::passwordAnswered, dialog,
            [dialog](bool accepted, const QString &reason) {
                if (!dialog->isChecking())
                    return;
                if (accepted)
                    dialog->passwordAccepted();
                else
                    dialog->passwordRefused(reason);
            });
    openDialog(dialog);
}

} // namespace DriveDesk
