// CompareWindow: the chosen values written into a side: a file directly, the file shown through
// the window's edits, the drive through the window's download.
#include "CompareWindow.h"

#include "CompareHost.h"
#include "ComparePaths.h"
#include "ComparisonModel.h"

#include "parameters/ParameterDocument.h"

#include <QLabel>
#include <QPushButton>

namespace DriveDesk {

void CompareWindow::updateWriteButtons()
{
    const QList<ComparisonRow> chosen = m_model->chosenRows();
    for (bool toA : { true, false }) {
        QPushButton *button = toA ? m_writeA : m_writeB;
        const std::optional<Side> &target = toA ? m_a : m_b;
        const int count = int(ChosenValues::from(chosen, toA).size());
        if (!target)
            button->setText(toA ? tr("Write to A") : tr("Write to B"));
        else if (toA)
            button->setText(tr("Write %n Value(s) to A (%1)", nullptr, count).arg(target->name));
        else
            button->setText(tr("Write %n Value(s) to B (%1)", nullptr, count).arg(target->name));
        bool can = target && target->writable && count > 0;
        if (can && target->source == Source::Drive)
            can = m_host && m_host->canWriteToDrive();
        if (can && target->source == Source::ShownFile)
            can = m_host && samePath(target->path, m_host->shownFilePath());
        button->setEnabled(can);
        button->setVisible(!target || target->writable);
    }
}


void CompareWindow::writeChosen(bool toA)
{
    if (!m_a || !m_b)
        return;
    // Copies: writing compares again, which replaces both sides.
    const Side target = toA ? *m_a : *m_b;
    const Side source = toA ? *m_b : *m_a;
    const QList<ChosenValue> values = ChosenValues::from(m_model->chosenRows(), toA);
    if (values.isEmpty() || !target.writable)
        return;
    switch (target.source) {
    case Source::Drive: {
        if (!m_host || !m_host->canWriteToDrive()) {
            showMessage(tr("Nothing written: no drive is connected that takes a download."));
            return;
        }
        m_host->writeToDrive(ChosenValues::selectionFor(source.origin, values));
        m_waitingForDrive = true;
        showMessage(tr("%n value(s) handed to the window's download to the drive; it shows "
                       "what it writes before it does.",
                       nullptr, int(values.size())));
        return;
    }
    case Source::ShownFile: {
        if (!m_host || !samePath(target.path, m_host->shownFilePath())) {
            showMessage(tr("Nothing written: the window no longer shows %1.")
                            .arg(shownPath(target.path)));
            return;
        }
        QStringList refusals;
        const int written = m_host->writeToShownFile(values, &refusals);
        compare();
        showRefusals(tr("%n value(s) changed in %1 as one undoable edit of the window; save the "
                        "file there to keep them.",
                        nullptr, written)
                         .arg(QFileInfo(target.path).fileName()),
                     refusals);
        return;
    }
    case Source::File:
        writeToFile(target, values);
        return;
    case Source::Defaults:
    case Source::SameAsA:
        return; // never a side's source once read
    }
}

void CompareWindow::driveReadAgain()
{
    if (!m_waitingForDrive)
        return;
    m_waitingForDrive = false;
    const bool driveCompared
        = (m_a && m_a->source == Source::Drive) || (m_b && m_b->source == Source::Drive);
    if (driveCompared && m_host && m_host->hasDrive())
        compare();
}

void CompareWindow::writeToFile(const Side &target, const QList<ChosenValue> &values)
{
    // Read again: only the chosen values change, whatever else happened to the file meanwhile.
    QString error;
    std::optional<DriveDescription> drive = ParameterDocument::load(target.path, &error);
    if (!drive) {
        showMessage(tr("Nothing written: could not read the file: %1").arg(error));
        return;
    }
    QStringList refusals;
    const int written = ChosenValues::apply(*drive, values, &refusals);
    if (written > 0 && !ParameterDocument::save(target.path, *drive, &error)) {
        showRefusals(tr("Could not save %1: %2. The file on disk is as it was.")
                         .arg(shownPath(target.path), error),
                     refusals);
        return;
    }
    compare();
    showRefusals(tr("%n value(s) written into %1.", nullptr, written).arg(shownPath(target.path)),
                 refusals);
}

} // namespace DriveDesk
