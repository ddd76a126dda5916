#pragma once

#include "frame/WindowFeature.h"

class QAction;

namespace DriveDesk {

// File > Export as CSV: what the window shows (the drive read, or the file open) for a
// spreadsheet, in core's CSV rule, saved whole or not at all.
class ExportFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit ExportFeature(WindowFrame &frame, QObject *parent = nullptr);

    void updateActions() override;

    bool exportCsv(const QString &path);

private:
    QAction *m_action = nullptr;
};

} // namespace DriveDesk
