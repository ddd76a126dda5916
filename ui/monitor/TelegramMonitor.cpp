#include "TelegramMonitor.h"

#include "TrafficFile.h"
#include "TrafficFilterModel.h"
#include "TrafficModel.h"

#include "client/DriveClient.h"
#include "frame/FrameSupport.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QScrollBar>
#include <QSettings>
#include <QStyle>
#include <QToolBar>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>
#include <climits>

namespace DriveDesk {

namespace {

const QString kHeaderKey = QStringLiteral("TelegramMonitor/header");

} // namespace

QSettings TelegramMonitor::settings()
{
    return QSettings(QStringLiteral("DriveDesk"), QStringLiteral("DriveDesk"));
}

TelegramMonitor::TelegramMonitor(QWidget *parent)
    : QDockWidget(tr("Telegram monitor"), parent)
    , m_model(new TrafficModel(this))
    , m_filter(new TrafficFilterModel(this))
{
    setObjectName(QStringLiteral("TelegramMonitor")); // QMainWindow::saveState() needs it
    m_filter->setTrafficModel(m_model);

    m_view = new QTreeView;
    m_view->setObjectName(QStringLiteral("telegramList"));
    m_view->setModel(m_filter);
    m_view->setRootIsDecorated(false);
    m_view->setItemsExpandable(false);
    m_view->setUniformRowHeights(true); // thousands of rows: no per-row height measuring
    m_view->setAllColumnsShowFocus(true);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    // keepTopRowsInView() counts in rows.
    m_view->setVerticalScrollMode(QAbstractItemView::ScrollPerItem);
    m_view->setTextElideMode(Qt::ElideRight);
    m_view->installEventFilter(this);

    // Widths for a typical telegram; the user's own widths are restored over them.
    const QFontMetrics metrics(m_view->font());
    const QFontMetrics fixed(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    QHeaderView *header = m_view->header();
    header->setStretchLastSection(true);
    header->resizeSection(TrafficModel::TimeColumn,
                          metrics.horizontalAdvance(QStringLiteral("00:00:00.000")) + 24);
    header->resizeSection(
        TrafficModel::DirectionColumn,
        metrics.horizontalAdvance(TrafficFormat::direction(TrafficRecord::Kind::Received)) + 48);
    header->resizeSection(TrafficModel::BytesColumn,
                          fixed.horizontalAdvance(QString(20 * 3, QLatin1Char('0'))));
    header->resizeSection(TrafficModel::CharactersColumn,
                          fixed.horizontalAdvance(QString(30, QLatin1Char('0'))));
    header->restoreState(settings().value(kHeaderKey).toByteArray());

    m_copyAction = new QAction(themedIcon("edit-copy", QStyle::SP_FileIcon),
                               tr("&Copy"), m_view);
    m_copyAction->setShortcut(QKeySequence::Copy);
    m_copyAction->setShortcutContext(Qt::WidgetShortcut);
    connect(m_copyAction, &QAction::triggered, this, &TelegramMonitor::copySelection);
    m_view->addAction(m_copyAction);
    m_view->setContextMenuPolicy(Qt::ActionsContextMenu);

    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("monitorStatus"));
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Wrapped: a long count ("... older telegrams dropped ...") must not widen the dock, and
    // with it the window past the screen, beside the scope.
    m_status->setWordWrap(true);
    m_notice = new QLabel;
    m_notice->setObjectName(QStringLiteral("monitorNotice"));
    m_notice->setWordWrap(true);
    m_notice->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_notice->hide();

    auto *content = new QWidget;
    auto *layout = new QVBoxLayout(content);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(createToolBar());
    layout->addWidget(m_view, 1);
    layout->addWidget(m_status);
    layout->addWidget(m_notice);
    setWidget(content);

    // Whether the list follows the newest telegram is the user's choice, made by scrolling:
    // away from the bottom it stays, back at the bottom it follows again. Only a visible list
    // has a position to judge; a closed dock keeps the choice for when it opens.
    connect(m_view->verticalScrollBar(), &QScrollBar::valueChanged, this, [this] {
        if (m_view->isVisible() && !m_inBatch)
            m_followNewest = isAtBottom();
    });
    m_view->viewport()->installEventFilter(this);
    connect(m_model, &TrafficModel::batchAboutToBeShown, this, [this] { m_inBatch = true; });
    connect(m_model, &TrafficModel::batchShown, this, [this] {
        m_inBatch = false;
        if (m_followNewest)
            m_view->scrollToBottom();
    });
    // A batch that overflows the capacity drops the oldest rows: whoever reads further up
    // keeps the same telegrams in view instead of seeing them slide away.
    connect(m_filter, &QAbstractItemModel::rowsRemoved, this,
            [this](const QModelIndex &, int first, int last) {
                if (m_inBatch && !m_followNewest && first == 0)
                    keepTopRowsInView(last - first + 1);
            });
    connect(m_model, &TrafficModel::countsChanged, this, &TelegramMonitor::updateStatus);
    updateCharactersColumn();
    updateStatus();
}

TelegramMonitor::~TelegramMonitor()
{
    settings().setValue(kHeaderKey, m_view->header()->saveState());
}

QWidget *TelegramMonitor::createToolBar()
{
    auto *toolBar = new QToolBar;
    toolBar->setObjectName(QStringLiteral("monitorToolBar"));
    toolBar->setIconSize(QSize(16, 16));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    m_pauseAction = toolBar->addAction(
        themedIcon("media-playback-pause", QStyle::SP_MediaPause), tr("Pause"));
    m_pauseAction->setCheckable(true);
    m_pauseAction->setToolTip(tr("Hold new telegrams back and show them on resume"));
    connect(m_pauseAction, &QAction::toggled, this, &TelegramMonitor::setPaused);

    QAction *clearAction = toolBar->addAction(
        themedIcon("edit-clear", QStyle::SP_DialogResetButton), tr("Clear"));
    clearAction->setToolTip(tr("Forget every telegram listed and held"));
    connect(clearAction, &QAction::triggered, this, &TelegramMonitor::clear);

    QAction *saveAction = toolBar->addAction(
        themedIcon("document-save-as", QStyle::SP_DialogSaveButton), tr("Save…"));
    saveAction->setToolTip(tr("Save the telegrams the filter shows to a CSV or text file"));
    connect(saveAction, &QAction::triggered, this, &TelegramMonitor::chooseFileAndSave);

    toolBar->addSeparator();
    m_filterEdit = new QLineEdit;
    m_filterEdit->setObjectName(QStringLiteral("monitorFilter"));
    m_filterEdit->setPlaceholderText(tr("Filter: meaning, hex bytes or characters"));
    m_filterEdit->setClearButtonEnabled(true);
    connect(m_filterEdit, &QLineEdit::textChanged, this, &TelegramMonitor::setFilterText);
    toolBar->addWidget(m_filterEdit);

    m_errorsOnlyBox = new QCheckBox(tr("Errors only"));
    m_errorsOnlyBox->setObjectName(QStringLiteral("monitorErrorsOnly"));
    connect(m_errorsOnlyBox, &QCheckBox::toggled, this, &TelegramMonitor::setErrorsOnly);
    toolBar->addWidget(m_errorsOnlyBox);
    return toolBar;
}

void TelegramMonitor::attach(DriveClient *client)
{
    if (m_trafficConnection)
        disconnect(m_trafficConnection);
    m_trafficConnection = {};
    if (!client)
        return;
    m_model->setProtocol(client->settings().protocol);
    updateCharactersColumn();
    m_trafficConnection = connect(client, &DriveClient::traffic, m_model,
                                  qOverload<const TrafficRecord &>(&TrafficModel::append));
}

void TelegramMonitor::follow(DriveClient *client)
{
    if (!client)
        return;
    const Protocol protocol = client->settings().protocol;
    connect(client, &DriveClient::traffic, m_model,
            [model = m_model, protocol](const TrafficRecord &record) {
                model->append(record, protocol);
            });
}

void TelegramMonitor::setDrive(std::shared_ptr<const DriveDescription> drive)
{
    m_model->setDrive(std::move(drive));
}

void TelegramMonitor::setPaused(bool paused)
{
    m_model->setPaused(paused);
    m_pauseAction->setChecked(paused);
    m_pauseAction->setText(paused ? tr("Resume") : tr("Pause"));
    m_pauseAction->setIcon(
        paused ? themedIcon("media-playback-start", QStyle::SP_MediaPlay)
               : themedIcon("media-playback-pause", QStyle::SP_MediaPause));
}

bool TelegramMonitor::isPaused() const
{
    return m_model->isPaused();
}

void TelegramMonitor::clear()
{
    m_model->clear();
    m_followNewest = true;
    showNotice({}, false);
}

void TelegramMonitor::setFilterText(const QString &text)
{
    m_filter->setFilterText(text);
    if (m_filterEdit->text() != text)
        m_filterEdit->setText(text);
    if (m_followNewest)
        m_view->scrollToBottom();
    updateStatus();
}

void TelegramMonitor::setErrorsOnly(bool on)
{
    m_filter->setErrorsOnly(on);
    m_errorsOnlyBox->setChecked(on);
    if (m_followNewest)
        m_view->scrollToBottom();
    updateStatus();
}

QString TelegramMonitor::statusText() const
{
    return m_status->text();
}

QString TelegramMonitor::noticeText() const
{
    return m_notice->text();
}

bool TelegramMonitor::eventFilter(QObject *watched, QEvent *event)
{
    // Opened, or resized, while following: the newest telegram is what is in view.
    if (watched == m_view->viewport()
        && (event->type() == QEvent::Show || event->type() == QEvent::Resize)
        && m_followNewest) {
        m_view->scrollToBottom();
    }
    // Ctrl+C in the list copies whole rows, even where the main window has its own Copy.
    if (watched == m_view
        && (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress)) {
        auto *key = static_cast<QKeyEvent *>(event);
        if (key->matches(QKeySequence::Copy)) {
            event->accept();
            if (event->type() == QEvent::KeyPress)
                copySelection();
            return true;
        }
    }
    return QDockWidget::eventFilter(watched, event);
}

void TelegramMonitor::updateStatus()
{
    const int rows = m_model->rowCount();
    QStringList parts;
    if (m_filter->isFiltering())
        parts << tr("%1 of %Ln telegram(s) shown", nullptr, rows)
                     .arg(QLocale().toString(m_filter->rowCount()));
    else
        parts << tr("%Ln telegram(s)", nullptr, rows);
    if (m_model->droppedCount() > 0)
        parts << tr("%Ln older telegram(s) dropped: the monitor keeps the latest %1", nullptr,
                    int(std::min<qint64>(m_model->droppedCount(), INT_MAX)))
                     .arg(QLocale().toString(m_model->capacity()));
    if (m_model->isPaused())
        parts << tr("paused: %Ln telegram(s) held, shown on resume", nullptr,
                    m_model->waitingCount());
    m_status->setText(parts.join(QStringLiteral(" · ")));
}

void TelegramMonitor::updateCharactersColumn()
{
    m_view->setColumnHidden(TrafficModel::CharactersColumn,
                            !TrafficFormat::isAscii(m_model->protocol()));
}

void TelegramMonitor::showNotice(const QString &text, bool problem)
{
    m_notice->setText(text);
    m_notice->setVisible(!text.isEmpty());
    QFont font = m_notice->font();
    font.setBold(problem);
    m_notice->setFont(font);
}

bool TelegramMonitor::isAtBottom() const
{
    const QScrollBar *bar = m_view->verticalScrollBar();
    return bar->value() >= bar->maximum();
}

void TelegramMonitor::keepTopRowsInView(int removedRows)
{
    QScrollBar *bar = m_view->verticalScrollBar();
    bar->setValue(std::max(bar->value() - removedRows, 0));
}

} // namespace DriveDesk
