#include "EditingFeature.h"

#include "DocumentEditor.h"
#include "EditController.h"
#include "WriteJournal.h"
#include "SetsDialog.h"

#include "frame/DriveSession.h"
#include "frame/FrameSupport.h"
#include "frame/ParameterBrowser.h"
#include "frame/ParameterEditing.h"
#include "frame/ParameterView.h"
#include "model/ParameterModel.h"
#include "session/ValueReads.h"

#include <QAction>
#include <QMenu>
#include <QProgressBar>
#include <QToolBar>
#include <QUndoStack>

namespace DriveDesk {

EditingFeature::EditingFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    QUndoStack *stack = frame.undoStack();
    // Own actions rather than the stack's: they also go off while the drive cannot be written.
    m_undoAction = new QAction(themedIcon("edit-undo", QStyle::SP_ArrowBack), tr("&Undo"), this);
    m_undoAction->setObjectName(QStringLiteral("undoAction"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    connect(m_undoAction, &QAction::triggered, stack, &QUndoStack::undo);
    m_redoAction
        = new QAction(themedIcon("edit-redo", QStyle::SP_ArrowForward), tr("&Redo"), this);
    m_redoAction->setObjectName(QStringLiteral("redoAction"));
    m_redoAction->setShortcut(QKeySequence::Redo);
    connect(m_redoAction, &QAction::triggered, stack, &QUndoStack::redo);
    // The menu names the write; the toolbar button stays short, its tooltip names it.
    m_undoAction->setIconText(tr("Undo"));
    m_redoAction->setIconText(tr("Redo"));
    connect(stack, &QUndoStack::undoTextChanged, this, [this](const QString &text) {
        m_undoAction->setText(text.isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(text));
        m_undoAction->setToolTip(text.isEmpty() ? tr("Undo") : tr("Undo %1").arg(text));
    });
    connect(stack, &QUndoStack::redoTextChanged, this, [this](const QString &text) {
        m_redoAction->setText(text.isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(text));
        m_redoAction->setToolTip(text.isEmpty() ? tr("Redo") : tr("Redo %1").arg(text));
    });
    connect(stack, &QUndoStack::canUndoChanged, this, [this] { this->frame().updateActions(); });
    connect(stack, &QUndoStack::canRedoChanged, this, [this] { this->frame().updateActions(); });

    m_resetAction = new QAction(themedIcon("edit-clear", QStyle::SP_DialogResetButton),
                                tr("Reset to &Default"), this);
    m_resetAction->setObjectName(QStringLiteral("resetAction"));
    m_resetAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    m_resetAction->setToolTip(tr("Set the selected values to the drive's default"));
    connect(m_resetAction, &QAction::triggered, this, &EditingFeature::resetToDefault);
    m_writeSetsAction = new QAction(tr("&Write to Sets..."), this);
    m_writeSetsAction->setObjectName(QStringLiteral("writeSetsAction"));
    m_writeSetsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    m_writeSetsAction->setToolTip(tr("Write a value to several parameter sets at once"));
    connect(m_writeSetsAction, &QAction::triggered, this, &EditingFeature::writeToSets);
    m_copySetAction = new QAction(tr("&Copy Set..."), this);
    m_copySetAction->setObjectName(QStringLiteral("copySetAction"));
    m_copySetAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
    m_copySetAction->setToolTip(tr("Copy every set-programmable value from one set to another"));
    connect(m_copySetAction, &QAction::triggered, this, &EditingFeature::copySet);

    QMenu *edit = frame.menu(WindowFrame::Menu::Edit);
    edit->addSeparator();
    edit->addAction(m_undoAction);
    edit->addAction(m_redoAction);
    edit->addSeparator();
    edit->addAction(m_resetAction);
    edit->addAction(m_writeSetsAction);
    edit->addAction(m_copySetAction);
    // Icons only in the toolbar (see MainWindow::createMenus): it must fit in every language.
    for (QAction *action : { m_undoAction, m_redoAction, m_resetAction })
        action->setPriority(QAction::LowPriority);
    QToolBar *bar = frame.toolBar();
    bar->addSeparator();
    bar->addAction(m_undoAction);
    bar->addAction(m_redoAction);
    bar->addAction(m_resetAction);
    frame.browser()->setContextActions({ m_resetAction, m_writeSetsAction });

    m_busy = new QProgressBar;
    m_busy->setObjectName(QStringLiteral("refreshProgress"));
    m_busy->setMaximumWidth(160);
    m_busy->hide();
    frame.addStatusWidget(m_busy);
    m_journal = new WriteJournal(frame, this);
}

void EditingFeature::attach(DriveSession *session)
{
    m_busy->hide();
    // It holds the old session's client, which goes after this.
    m_journal->attach(nullptr, nullptr);
    delete m_edit;
    m_edit = nullptr;
    if (!session)
        return;
    auto *edit = new EditController(session->client(), frame().model(), frame().undoStack(), this);
    m_edit = edit;
    m_journal->attach(session, edit);
    connect(edit, &EditController::message, this,
            [this](const QString &text) { frame().showMessage(text); });
    connect(session, &DriveSession::valuesRequested, edit, &EditController::refresh);
    connect(session, &DriveSession::writesLost, edit, &EditController::forgetWrites);
    connect(edit, &EditController::busyChanged, this, [this](bool busy) {
        m_busy->setVisible(busy);
        frame().updateActions();
    });
    connect(edit, &EditController::progress, this, [this](int done, int total) {
        m_busy->setRange(0, total);
        m_busy->setValue(done);
    });
}

void EditingFeature::attachFile(const QString &path)
{
    delete m_document;
    m_document = nullptr;
    if (path.isEmpty())
        return;
    m_document = new DocumentEditor(frame().model(), frame().undoStack(), this);
    connect(m_document, &DocumentEditor::message, this,
            [this](const QString &text) { frame().showMessage(text); });
}

ParameterEditing *EditingFeature::editing() const
{
    if (m_document)
        return m_document;
    return m_edit && frame().isReady() ? m_edit : nullptr;
}

void EditingFeature::readOpenedValues(PasswordLevel from, PasswordLevel to)
{
    if (m_edit)
        m_edit->readAgain(valuesOpenedBy(frame().state()->description(), from, to));
}

void EditingFeature::updateActions()
{
    const ParameterEditing *editing = frame().editing();
    const bool ready = editing != nullptr;
    const bool selected = frame().browser()->hasSelectedParameter();
    m_resetAction->setEnabled(ready && selected);
    m_writeSetsAction->setEnabled(ready && selected);
    m_copySetAction->setEnabled(ready);
    // An undo while a write is still on its way could leave the stack and the drive apart.
    const bool idle = ready && !editing->isBusy();
    m_undoAction->setEnabled(idle && frame().undoStack()->canUndo());
    m_redoAction->setEnabled(idle && frame().undoStack()->canRedo());
}

void EditingFeature::resetToDefault()
{
    ParameterEditing *editing = frame().editing();
    if (!editing)
        return;
    ParameterModel *model = frame().model();
    QStringList skipped;
    const QList<QPair<quint16, quint8>> selected = frame().browser()->selectedParameters();
    for (const auto &[address, setMask] : selected) {
        if (model->state()->isEditable(address))
            editing->resetToDefault(address, setMask);
        else
            skipped << model->state()->editText(address).id();
    }
    if (skipped.isEmpty())
        return;
    constexpr int kNamed = 8;
    const QString names = skipped.mid(0, kNamed).join(QStringLiteral(", "));
    if (skipped.size() > kNamed) {
        frame().showMessage(tr("Not reset, read-only or above the password level in force: %1 "
                               "and %n more",
                               nullptr, int(skipped.size() - kNamed))
                                .arg(names));
    } else {
        frame().showMessage(
            tr("Not reset, read-only or above the password level in force: %1").arg(names));
    }
}

void EditingFeature::writeToSets()
{
    if (!frame().editing())
        return;
    ParameterModel *model = frame().model();
    // The value of the current cell (or the parameter's first set) goes to the sets chosen.
    const QModelIndex current = frame().browser()->view()->currentIndex();
    const QList<QPair<quint16, quint8>> selected = frame().browser()->selectedParameters();
    if (selected.isEmpty())
        return;
    const quint16 address = current.isValid()
        ? current.data(ParameterModel::AddressRole).value<quint16>()
        : selected.constFirst().first;
    const ParameterDescription *parameter = model->state()->parameter(address);
    if (!parameter)
        return;
    const QString id = model->state()->editText(address).id();
    if (!parameter->isSetProgrammable()) {
        frame().showMessage(
            tr("%1 is not set-programmable: it holds one value for every set.").arg(id));
        return;
    }
    if (const QString refusal = frame().state()->editRefusal(address); !refusal.isEmpty()) {
        frame().showMessage(refusal);
        return;
    }
    const int set = std::max(0, ParameterModel::setOfColumn(current.column()));
    if (!model->state()->value(address, set)) {
        frame().showMessage(tr("%1 has no value read in set %2 to write.").arg(id).arg(set));
        return;
    }
    auto *dialog = new SetsDialog(SetsDialog::Mode::ChooseSets, frame().frameWidget());
    dialog->setWindowTitle(tr("Write to Sets"));
    dialog->setPrompt(
        tr("Write %1 to %2 in:")
            .arg(model->valueIndex(address, set).data(Qt::DisplayRole).toString(), id));
    dialog->setActiveSet(activeSet());
    dialog->setSetMask(quint8(1u << set));
    connect(dialog, &QDialog::accepted, this, [this, dialog, address, set, id] {
        // The value as it is now: polling or another write may have changed it meanwhile.
        ParameterModel *model = frame().model();
        const std::optional<qint32> now
            = frame().editing() ? model->state()->value(address, set) : std::nullopt;
        if (!now) {
            frame().showMessage(tr("%1 has no value read in set %2 to write.").arg(id).arg(set));
            return;
        }
        QString problem;
        if (!model->requestWrite(address, dialog->setMask(), *now, &problem))
            frame().showMessage(problem);
    });
    openDialog(dialog);
}

void EditingFeature::copySet()
{
    if (!frame().editing())
        return;
    auto *dialog = new SetsDialog(SetsDialog::Mode::CopySet, frame().frameWidget());
    dialog->setWindowTitle(tr("Copy Set"));
    dialog->setPrompt(tr("Copy every set-programmable value you may change from one set to "
                         "another:"));
    const int active = activeSet();
    dialog->setActiveSet(active);
    const int from = std::max(active, 0);
    dialog->setCopy(from, (from + 1) % kParameterSets);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        if (ParameterEditing *editing = frame().editing())
            editing->copySet(dialog->fromSet(), dialog->toSet());
    });
    openDialog(dialog);
}

int EditingFeature::activeSet() const
{
    // A parameter file has no set the drive works with.
    return frame().session() ? frame().session()->activeSet() : -1;
}

bool EditingFeature::journalsWrites() const
{
    return m_journal->isOn();
}

} // namespace DriveDesk
