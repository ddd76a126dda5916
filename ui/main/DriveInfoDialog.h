#pragma once

#include "link/ConnectionSettings.h"
#include "parameters/DriveDescription.h"

#include <QDialog>

class QTextBrowser;

namespace DriveDesk {

// What is known about the connected drive: its identification text (service 13), the
// identification parameters it has (inverter identifier, power unit, software version, serial
// number ...), the connection and how many groups and parameters it holds. All of it can be
// selected and copied.
class DriveInfoDialog : public QDialog
{
    Q_OBJECT
public:
    struct Line
    {
        QString label;
        QString value;
    };

    DriveInfoDialog(const DriveDescription &drive, const ConnectionSettings &settings,
                    QWidget *parent = nullptr);

    // The lines shown, in order; parameters the drive does not have are left out.
    static QList<Line> lines(const DriveDescription &drive, const ConnectionSettings &settings);
    // "Label: value" per line, as the Copy button puts it on the clipboard.
    QString plainText() const;

private:
    QList<Line> m_lines;
    QTextBrowser *m_text = nullptr;
};

} // namespace DriveDesk
