#pragma once

#include "CompareHost.h"
#include "CompareWindow.h"

#include "frame/WindowFeature.h"

#include <QPointer>

namespace DriveDesk {


// "Compare..." in the window: opens the compare window (one, non-modal) and is its host: the
// drive the window is connected to, the file it shows instead, and the way to the window's
// download for values chosen to go to the drive.
class CompareFeature : public WindowFeature, public CompareHost
{
    Q_OBJECT
public:
    explicit CompareFeature(WindowFrame &frame, QObject *parent = nullptr);

    // Shows the compare window, made at the first call.
    CompareWindow *showCompareWindow();
    CompareWindow *compareWindow() const { return m_window; }

    void attach(DriveSession *session) override;
    void updateActions() override;

    // CompareHost
    bool hasDrive() const override;
    DriveDescription drive() const override;
    QString shownFilePath() const override;
    DriveDescription shownFile() const override;
    int writeToShownFile(const QList<ChosenValue> &values, QStringList *refusals) override;
    bool canWriteToDrive() const override;
    void chooseFile(const QString &title,
                    std::function<void(const QString &path)> chosen) override;
    void writeToDrive(const DriveDescription &selection) override;

signals:
    // The user chose values in the compare window to write to the connected drive: the
    // selection (ChosenValues::selectionFor) holds them and the identification, every other
    // value empty. The window's download plans, checks, shows a last look and writes; the
    // compare window offers the drive as a target only while this signal is connected.
    void writeToDriveRequested(const DriveDesk::DriveDescription &selection);

private:
    QAction *m_compareAction = nullptr;
    QPointer<CompareWindow> m_window;
    bool m_editsBusy = false; // the drive's edits were busy at the last updateActions()
};

} // namespace DriveDesk
