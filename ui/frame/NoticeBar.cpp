#include "NoticeBar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStyle>

namespace DriveDesk {

NoticeBar::NoticeBar(QWidget *parent)
    : QFrame(parent)
{
    setObjectName(QStringLiteral("noticeBar"));
    setFrameShape(QFrame::StyledPanel);
    // The palette's own highlight-free window colour keeps it readable in dark themes too.
    setAutoFillBackground(true);
    setBackgroundRole(QPalette::AlternateBase);

    m_icon = new QLabel;
    m_text = new QLabel;
    m_text->setObjectName(QStringLiteral("noticeText"));
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("noticeProgress"));
    m_progress->setMinimumWidth(240);
    m_progress->setTextVisible(true);
    m_cancel = new QPushButton(tr("&Cancel"));
    m_cancel->setObjectName(QStringLiteral("noticeCancel"));
    m_reconnect = new QPushButton(tr("&Reconnect"));
    m_reconnect->setObjectName(QStringLiteral("noticeReconnect"));
    m_connect = new QPushButton(tr("C&onnect..."));
    m_connect->setObjectName(QStringLiteral("noticeConnect"));

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 4);
    layout->addWidget(m_icon);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_progress);
    layout->addWidget(m_cancel);
    layout->addWidget(m_reconnect);
    layout->addWidget(m_connect);

    connect(m_cancel, &QPushButton::clicked, this, &NoticeBar::cancelClicked);
    connect(m_reconnect, &QPushButton::clicked, this, &NoticeBar::reconnectClicked);
    connect(m_connect, &QPushButton::clicked, this, &NoticeBar::connectClicked);
    hide();
}

void NoticeBar::showKind(Kind kind, const QString &text, bool offerReconnect)
{
    m_kind = kind;
    m_text->setText(text);
    const int size = style()->pixelMetric(QStyle::PM_SmallIconSize);
    const QStyle::StandardPixmap icon = kind == Kind::Problem ? QStyle::SP_MessageBoxWarning
        : kind == Kind::Progress                              ? QStyle::SP_BrowserReload
                                                              : QStyle::SP_MessageBoxInformation;
    m_icon->setPixmap(style()->standardIcon(icon).pixmap(size, size));
    m_progress->setVisible(kind == Kind::Progress);
    m_cancel->setVisible(kind == Kind::Progress);
    m_reconnect->setVisible(offerReconnect);
    m_connect->setVisible(kind != Kind::Progress);
    show();
}

void NoticeBar::showProgress(const QString &text, int value, int maximum)
{
    m_progress->setRange(0, maximum);
    m_progress->setValue(value);
    showKind(Kind::Progress, text, false);
}

void NoticeBar::showProblem(const QString &text)
{
    showKind(Kind::Problem, text, true);
}

void NoticeBar::showInformation(const QString &text, bool offerReconnect)
{
    showKind(Kind::Information, text, offerReconnect);
}

QString NoticeBar::text() const
{
    return m_text->text();
}

} // namespace DriveDesk
