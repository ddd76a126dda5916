#include "JournalDock.h"

#include "JournalReader.h"
#include "JournalTableModel.h"

#include <QAction>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

namespace DriveDesk {

namespace {

const QString kSettingsGroup = QStringLiteral("journalView");

// Which reading an answer belongs to, beside the filters' generation.
enum Reading { Page, Newer, Older };

int tagOf(int generation, Reading reading)
{
    return generation * 4 + reading;
}

} // namespace

JournalDock::JournalDock(QWidget *parent, const QString &journalPath)
    : QDockWidget(tr("Journal"), parent)
    , m_reader(new JournalReader(journalPath, this))
    , m_model(new JournalTableModel(this))
    , m_proxy(new QSortFilterProxyModel(this))
{
    setObjectName(QStringLiteral("journalDock"));
    auto *content = new QWidget(this);
    auto *layout = new QVBoxLayout(content);
    layout->setContentsMargins(4, 4, 4, 4);

    // No mnemonics here: the window's Alt+letters are taken; Tab walks the fields in order.
    m_filters = new QWidget(content);
    auto *grid = new QGridLayout(m_filters);
    grid->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_filters);
    const auto place = [grid](QLineEdit *field, int row, int column) {
        grid->addWidget(field->property("label").value<QLabel *>(), row, column * 2);
        grid->addWidget(field, row, column * 2 + 1);
    };
    m_drive = addField(tr("Drive:"), tr("serial number, link or link@address"),
                       QStringLiteral("journalDrive"));
    m_parameter = addField(tr("Parameter:"), tr("op.28 or 0x0A1C"),
                           QStringLiteral("journalParameter"));
    m_user = addField(tr("User:"), tr("login name"), QStringLiteral("journalUser"));
    m_since = addField(tr("Since:"), tr("2026-11-24 or 2026-11-24 10:42"),
                       QStringLiteral("journalSince"));
    m_until = addField(tr("Until:"), tr("2026-11-24 or 2026-11-24 10:42"),
                       QStringLiteral("journalUntil"));
    m_search = addField(tr("Search:"), tr("any field of the entries shown"),
                        QStringLiteral("journalSearch"));
    place(m_drive, 0, 0);
    place(m_parameter, 0, 1);
    place(m_user, 0, 2);
    place(m_since, 1, 0);
    place(m_until, 1, 1);
    place(m_search, 1, 2);
    m_thisDrive = new QPushButton(tr("This Drive"), m_filters);
    m_thisDrive->setObjectName(QStringLiteral("journalThisDrive"));
    m_thisDrive->setToolTip(tr("Show the entries of the connected drive"));
    grid->addWidget(m_thisDrive, 0, 6);

    m_proxy->setSourceModel(m_model);
    m_proxy->setFilterRole(JournalTableModel::SearchTextRole);
    m_proxy->setFilterKeyColumn(0);
    m_view = new QTableView(content);
    m_view->setObjectName(QStringLiteral("journalTable"));
    m_view->setModel(m_proxy);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setWordWrap(false);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 6);
    m_view->horizontalHeader()->setStretchLastSection(true);
    // The whole time, until the user sizes the column (the widths are remembered).
    m_view->horizontalHeader()->resizeSection(
        JournalTableModel::TimeColumn,
        m_view->fontMetrics().horizontalAdvance(QStringLiteral("2026-11-28 10:42:00")) + 16);
    m_view->setContextMenuPolicy(Qt::ActionsContextMenu);
    layout->addWidget(m_view, 1);

    auto *buttons = new QHBoxLayout;
    m_status = new QLabel(content);
    m_status->setObjectName(QStringLiteral("journalStatus"));
    buttons->addWidget(m_status, 1);
    m_older = new QPushButton(tr("Load Older"), content);
    m_older->setObjectName(QStringLiteral("journalLoadOlder"));
    m_older->setToolTip(tr("Read the %n entries before the oldest shown", nullptr, kPageSize));
    auto *refresh = new QPushButton(tr("Refresh"), content);
    refresh->setObjectName(QStringLiteral("journalRefresh"));
    m_revert = new QPushButton(tr("Revert..."), content);
    m_revert->setObjectName(QStringLiteral("journalRevert"));
    m_revert->setToolTip(tr("Write the values before the selected entries back to the drive, "
                            "after a last look at what will change"));
    buttons->addWidget(m_older);
    buttons->addWidget(refresh);
    buttons->addWidget(m_revert);
    layout->addLayout(buttons);
    setWidget(content);

    auto *revertAction = new QAction(tr("Revert..."), m_view);
    revertAction->setObjectName(QStringLiteral("journalRevertAction"));
    m_view->addAction(revertAction);

    for (QLineEdit *field : { m_drive, m_parameter, m_user, m_since, m_until })
        connect(field, &QLineEdit::editingFinished, this, [this, field] {
            if (field->isModified()) {
                field->setModified(false);
                reload();
            }
        });
    connect(m_search, &QLineEdit::textChanged, this, [this](const QString &text) {
        m_proxy->setFilterFixedString(text.trimmed().toLower());
        updateStatus();
    });
    connect(m_thisDrive, &QPushButton::clicked, this, [this] {
        m_drive->setText(m_connectedDrive);
        reload();
    });
    connect(m_older, &QPushButton::clicked, this, [this] {
        std::optional<JournalFilter> older = filter();
        if (!older || m_model->rowCount() == 0)
            return;
        older->setBeforeEntry(m_model->oldestId());
        older->setNewest(kPageSize);
        m_reader->read(*older, tagOf(m_generation, Older));
        updateButtons();
    });
    connect(refresh, &QPushButton::clicked, this, &JournalDock::refresh);
    const auto revert = [this] {
        if (m_revertEnabled && !selectedEntries().isEmpty())
            emit revertRequested(selectedEntries());
    };
    connect(m_revert, &QPushButton::clicked, this, revert);
    connect(revertAction, &QAction::triggered, this, revert);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &JournalDock::updateButtons);
    connect(m_reader, &JournalReader::done, this, &JournalDock::onRead);

    QSettings settings;
    settings.beginGroup(kSettingsGroup);
    for (QLineEdit *field : { m_drive, m_parameter, m_user, m_since, m_until })
        field->setText(settings.value(field->objectName()).toString());
    m_view->horizontalHeader()->restoreState(settings.value(QStringLiteral("columns")).toByteArray());
    updateButtons();
}

JournalDock::~JournalDock() = default;

QLineEdit *JournalDock::addField(const QString &label, const QString &placeholder,
                                 const QString &name)
{
    auto *field = new QLineEdit(m_filters);
    field->setObjectName(name);
    field->setPlaceholderText(placeholder);
    field->setClearButtonEnabled(true);
    auto *text = new QLabel(label, m_filters);
    text->setBuddy(field);
    field->setProperty("label", QVariant::fromValue(text));
    return field;
}

void JournalDock::saveSettings() const
{
    QSettings settings;
    settings.beginGroup(kSettingsGroup);
    for (QLineEdit *field : { m_drive, m_parameter, m_user, m_since, m_until })
        settings.setValue(field->objectName(), field->text().trimmed());
    settings.setValue(QStringLiteral("columns"), m_view->horizontalHeader()->saveState());
}

void JournalDock::showEvent(QShowEvent *event)
{
    QDockWidget::showEvent(event);
    if (!m_loaded)
        reload();
}

std::optional<JournalFilter> JournalDock::filter()
{
    JournalFilter filter;
    QString error;
    using Setter = bool (JournalFilter::*)(const QString &, QString *);
    const std::pair<QLineEdit *, Setter> fields[] = {
        { m_drive, &JournalFilter::setDrive },
        { m_parameter, &JournalFilter::setParameter },
        { m_since, &JournalFilter::setSince },
        { m_until, &JournalFilter::setUntil },
    };
    for (const auto &[field, set] : fields) {
        if (!field->text().trimmed().isEmpty() && !(filter.*set)(field->text(), &error)) {
            m_problem = error;
            field->setFocus();
            return std::nullopt;
        }
    }
    filter.setUser(m_user->text().trimmed());
    if (filter.since().isValid() && filter.until().isValid() && filter.until() <= filter.since()) {
        m_problem = tr("'%1' is not after '%2'").arg(m_until->text(), m_since->text());
        return std::nullopt;
    }
    m_problem.clear();
    return filter;
}

void JournalDock::reload()
{
    ++m_generation;
    m_loaded = true;
    std::optional<JournalFilter> page = filter();
    if (!page) {
        m_model->setEntries({});
        m_moreOlder = false;
        updateStatus();
        updateButtons();
        return;
    }
    page->setNewest(kPageSize);
    m_reader->read(*page, tagOf(m_generation, Page));
    updateStatus();
    updateButtons();
}

void JournalDock::refresh()
{
    if (!m_loaded)
        return reload(); // nothing read yet: the newest page
    std::optional<JournalFilter> newer = filter();
    if (!newer)
        return;
    newer->setAfterEntry(m_model->newestId());
    m_reader->read(*newer, tagOf(m_generation, Newer));
}

void JournalDock::onRead(const JournalReading &reading)
{
    if (reading.tag / 4 != m_generation)
        return; // read for filters changed since
    if (!reading.error.isEmpty()) {
        m_problem = reading.error;
    } else {
        switch (Reading(reading.tag % 4)) {
        case Page:
            m_model->setEntries(reading.entries);
            m_moreOlder = reading.entries.size() >= kPageSize;
            break;
        case Newer:
            m_model->addNewer(reading.entries);
            break;
        case Older:
            m_model->addOlder(reading.entries);
            m_moreOlder = reading.entries.size() >= kPageSize;
            break;
        }
    }
    updateStatus();
    updateButtons();
    emit entriesRead();
}

void JournalDock::setConnectedDrive(const QString &name)
{
    m_connectedDrive = name;
    updateButtons();
}

void JournalDock::setRevertEnabled(bool enabled)
{
    m_revertEnabled = enabled;
    updateButtons();
}

QList<qint64> JournalDock::selectedEntries() const
{
    QList<qint64> ids;
    for (const QModelIndex &index : m_view->selectionModel()->selectedRows())
        ids << index.data(JournalTableModel::EntryIdRole).toLongLong();
    std::sort(ids.begin(), ids.end());
    return ids;
}

bool JournalDock::isReading() const
{
    return m_reader->isReading();
}

QString JournalDock::statusText() const
{
    return m_status->text();
}

void JournalDock::updateStatus()
{
    if (!m_problem.isEmpty()) {
        m_status->setText(m_problem);
        return;
    }
    if (m_reader->isReading() && m_model->rowCount() == 0) {
        m_status->setText(tr("Reading the journal..."));
        return;
    }
    const int read = m_model->rowCount();
    const int shown = m_proxy->rowCount();
    QString text = shown == read ? tr("%n entries", nullptr, read)
                                 : tr("%1 of %n entries match the search", nullptr, read)
                                       .arg(shown);
    if (m_moreOlder)
        text += QStringLiteral("; ") + tr("older ones not read yet");
    m_status->setText(text);
}

void JournalDock::updateButtons()
{
    m_older->setEnabled(m_moreOlder);
    m_thisDrive->setEnabled(!m_connectedDrive.isEmpty());
    const bool selected = m_view->selectionModel() && m_view->selectionModel()->hasSelection();
    m_revert->setEnabled(m_revertEnabled && selected);
    for (QAction *action : m_view->actions())
        action->setEnabled(m_revertEnabled && selected);
}

} // namespace DriveDesk
