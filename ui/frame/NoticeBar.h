#pragma once

#include <QFrame>

class QLabel;
class QProgressBar;
class QPushButton;

namespace DriveDesk {

// A bar across the top of the window that says what is going on with the connection where
// the user is looking: the scan's progress with Cancel, a lost link with Reconnect, or how to
// connect. Hidden when there is nothing to say.
class NoticeBar : public QFrame
{
    Q_OBJECT
public:
    enum class Kind : quint8 { Progress, Problem, Information };

    explicit NoticeBar(QWidget *parent = nullptr);

    // A running job: text, a progress bar (maximum 0: busy) and Cancel.
    void showProgress(const QString &text, int value, int maximum);
    // Something went wrong with the connection: text, Reconnect and Connect... .
    void showProblem(const QString &text);
    // A hint: text, Connect... and, when asked for, Reconnect.
    void showInformation(const QString &text, bool offerReconnect = false);

    Kind kind() const { return m_kind; }
    QString text() const;

signals:
    void cancelClicked();
    void reconnectClicked();
    void connectClicked();

private:
    void showKind(Kind kind, const QString &text, bool offerReconnect);

    Kind m_kind = Kind::Information;
    QLabel *m_icon = nullptr;
    QLabel *m_text = nullptr;
    QProgressBar *m_progress = nullptr;
    QPushButton *m_cancel = nullptr;
    QPushButton *m_reconnect = nullptr;
    QPushButton *m_connect = nullptr;
};

} // namespace DriveDesk
