#include "CompareFeature.h"

#include "CompareWindow.h"

#include "frame/DriveSession.h"
#include "frame/ParameterEditing.h"
#include "model/ParameterModel.h"

#include <QAction>
#include <QMenu>
#include <QMetaMethod>
#include <QUndoStack>

namespace DriveDesk {

CompareFeature::CompareFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_compareAction = new QAction(tr("Co&mpare..."), this);
    m_compareAction->setObjectName(QStringLiteral("compareAction"));
    m_compareAction->setToolTip(
        tr("Compare the drive, parameter files and defaults, and write chosen values"));
    connect(m_compareAction, &QAction::triggered, this, [this] { showCompareWindow(); });
    QMenu *view = frame.menu(WindowFrame::Menu::View);
    view->addSeparator();
    view->addAction(m_compareAction);
}

CompareWindow *CompareFeature::showCompareWindow()
{
    if (!m_window) {
        m_window = new CompareWindow(this, frame().frameWidget());
        m_window->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_window->show();
    m_window->raise();
    m_window->activateWindow();
    return m_window;
}

void CompareFeature::attach(DriveSession *session)
{
    Q_UNUSED(session)
    m_editsBusy = false;
    if (m_window)
        m_window->updateSources();
}

void CompareFeature::updateActions()
{
    // The window reads the drive again after a download, and its edits are idle once it has:
    // the compare window then sees what the drive holds now.
    const ParameterEditing *editing = frame().session() ? frame().editing() : nullptr;
    const bool busy = editing && editing->isBusy();
    if (m_editsBusy && !busy && m_window)
        m_window->driveReadAgain();
    m_editsBusy = busy;
    if (m_window)
        m_window->updateSources();
}

bool CompareFeature::hasDrive() const
{
    return frame().isReady();
}

DriveDescription CompareFeature::drive() const
{
    return hasDrive() ? frame().state()->description() : DriveDescription();
}

QString CompareFeature::shownFilePath() const
{
    // The window shows a file or a drive, never both.
    return frame().session() ? QString() : frame().parameterFilePath();
}

DriveDescription CompareFeature::shownFile() const
{
    return shownFilePath().isEmpty() ? DriveDescription() : frame().state()->description();
}

int CompareFeature::writeToShownFile(const QList<ChosenValue> &values, QStringList *refusals)
{
    if (shownFilePath().isEmpty() || !frame().editing())
        return 0;
    // The same rule as for a file on disk (what a download would write, within the limits),
    // then each value as if typed into the table: the file's editor makes it an edit.
    DriveDesk::DriveDescription checked = frame().state()->description();
    QList<ChosenValue> accepted;
    for (const ChosenValue &value : values) {
        if (ChosenValues::apply(checked, { value }, refusals) == 1)
            accepted.append(value);
    }
    if (accepted.isEmpty())
        return 0;
    QUndoStack *stack = frame().undoStack();
    stack->beginMacro(tr("Write %n compared value(s)", nullptr, int(accepted.size())));
    int written = 0;
    for (const ChosenValue &value : std::as_const(accepted)) {
        QString error;
        if (frame().model()->requestWrite(value.address, quint8(1u << value.set), value.raw,
                                          &error)) {
            ++written;
        } else if (refusals) {
            refusals->append(error);
        }
    }
    stack->endMacro();
    frame().updateActions();
    return written;
}

bool CompareFeature::canWriteToDrive() const
{
    return frame().isReady()
        && isSignalConnected(QMetaMethod::fromSignal(&CompareFeature::writeToDriveRequested));
}

void CompareFeature::writeToDrive(const DriveDescription &selection)
{
    if (canWriteToDrive())
        emit writeToDriveRequested(selection);
}

void CompareFeature::chooseFile(const QString &title,
                                std::function<void(const QString &path)> chosen)
{
    frame().chooseParameterFile(title, std::move(chosen));
}

} // namespace DriveDesk
