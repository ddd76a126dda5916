#pragma once

#include "frame/WindowFeature.h"

#include <QPointer>

class QLabel;

namespace DriveDesk {

// The drive's parameter sets in the window: the active set (Fr.02) and the set pointer (Fr.09)
// in the status bar, and the active set's column marked in the table, following every reading
// of either.
class SetsFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit SetsFeature(WindowFrame &frame, QObject *parent = nullptr);

    void attach(DriveSession *session) override;

private:
    void update();

    QLabel *m_label = nullptr;
    QPointer<DriveSession> m_session;
};

} // namespace DriveDesk
