#pragma once

#include "session/DownloadRun.h"

#include <QDialog>

#include <array>

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QTreeWidget;

namespace DriveDesk {

// The window's download of a parameter file to the drive, as DownloadRun goes: the drive being
// read, then a last look at every value to write (and what is left, and why the checks refuse),
// with the sets to write and the choice to overrule the checks, then the writing with its
// progress and Stop, then the report. Never modal; closing it while it writes only stops it.
class DownloadDialog : public QDialog
{
    Q_OBJECT
public:
    // `run` becomes the dialog's; `source` names what is written for the user ("the values
    // of FILE", "the values chosen in the compare window").
    DownloadDialog(DownloadRun *run, const QString &source, QWidget *parent = nullptr);

    DownloadRun *run() const { return m_run; }

signals:
    // The download wrote to the drive (all, part, or a value whose answer was lost).
    void wrote();

public slots:
    void reject() override;

private:
    void showReading(int done, int total, const QString &what);
    void showPlan(const DownloadPlan &plan);
    void showFailure(const QString &reason);
    void showReport(const DownloadReport &report);
    void changeOptions();
    void write();
    void fitValueColumns();

protected:
    void resizeEvent(QResizeEvent *event) override;

private:

    DownloadRun *const m_run;
    QLabel *m_status = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_problems = nullptr;
    QCheckBox *m_force = nullptr;
    QWidget *m_setRow = nullptr;
    std::array<QCheckBox *, 8> m_sets {};
    QTreeWidget *m_list = nullptr;
    QLabel *m_summary = nullptr;
    QPlainTextEdit *m_report = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    QPushButton *m_write = nullptr;
};

} // namespace DriveDesk
