#include "DownloadDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QResizeEvent>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace DriveDesk {

namespace {

enum Column { Id, Name, Sets, Now, Then, Note, Columns };

} // namespace

DownloadDialog::DownloadDialog(DownloadRun *run, const QString &source, QWidget *parent)
    : QDialog(parent)
    , m_run(run)
{
    m_run->setParent(this);
    setObjectName(QStringLiteral("downloadDialog"));
    setWindowTitle(tr("Download to the Drive"));
    auto *layout = new QVBoxLayout(this);
    auto *title = new QLabel(tr("Writes %1 to the drive, each read back.").arg(source));
    title->setObjectName(QStringLiteral("downloadIntro"));
    title->setWordWrap(true);
    layout->addWidget(title);

    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("downloadStatus"));
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    m_progress = new QProgressBar;
    layout->addWidget(m_progress);

    m_problems = new QLabel;
    m_problems->setObjectName(QStringLiteral("downloadProblems"));
    m_problems->setWordWrap(true);
    m_problems->setTextFormat(Qt::RichText);
    m_problems->hide();
    layout->addWidget(m_problems);
    m_force = new QCheckBox(tr("Write all the same (the checks above are &overruled)"));
    m_force->setObjectName(QStringLiteral("downloadForce"));
    m_force->hide();
    connect(m_force, &QCheckBox::toggled, this, &DownloadDialog::changeOptions);
    layout->addWidget(m_force);

    m_setRow = new QWidget;
    auto *sets = new QHBoxLayout(m_setRow);
    sets->setContentsMargins(0, 0, 0, 0);
    sets->addWidget(new QLabel(tr("Sets to write:")));
    for (int set = 0; set < int(m_sets.size()); ++set) {
        m_sets[std::size_t(set)] = new QCheckBox(QString::number(set));
        m_sets[std::size_t(set)]->setObjectName(QStringLiteral("downloadSet%1").arg(set));
        m_sets[std::size_t(set)]->setChecked(true);
        connect(m_sets[std::size_t(set)], &QCheckBox::toggled, this, &DownloadDialog::changeOptions);
        sets->addWidget(m_sets[std::size_t(set)]);
    }
    sets->addStretch();
    m_setRow->hide();
    layout->addWidget(m_setRow);

    m_list = new QTreeWidget;
    m_list->setObjectName(QStringLiteral("downloadList"));
    m_list->setRootIsDecorated(false);
    m_list->setAlternatingRowColors(true);
    m_list->setHeaderLabels({ tr("Parameter"), tr("Name"), tr("Sets"), tr("Drive now"),
                              tr("To write"), tr("Note") });
    // Long plaintexts must not push "To write" out of the dialog: the name takes the room
    // there is, the values and notes a capped width (fitValueColumns()), cut in the middle
    // and whole in their tool tips.
    QHeaderView *header = m_list->header();
    header->setStretchLastSection(false);
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setSectionResizeMode(Name, QHeaderView::Stretch);
    m_list->setTextElideMode(Qt::ElideMiddle);
    m_list->hide();
    layout->addWidget(m_list, 1);
    m_summary = new QLabel;
    m_summary->setObjectName(QStringLiteral("downloadSummary"));
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);

    m_report = new QPlainTextEdit;
    m_report->setObjectName(QStringLiteral("downloadReport"));
    m_report->setReadOnly(true);
    m_report->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_report->hide();
    layout->addWidget(m_report, 1);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Cancel);
    m_write = m_buttons->addButton(tr("Write"), QDialogButtonBox::AcceptRole);
    m_write->setObjectName(QStringLiteral("downloadWrite"));
    m_write->setEnabled(false);
    connect(m_write, &QPushButton::clicked, this, &DownloadDialog::write);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &DownloadDialog::reject);
    layout->addWidget(m_buttons);
    resize(860, 560);

    connect(m_run, &DownloadRun::progress, this, &DownloadDialog::showReading);
    connect(m_run, &DownloadRun::planned, this, &DownloadDialog::showPlan);
    connect(m_run, &DownloadRun::failed, this, &DownloadDialog::showFailure);
    connect(m_run, &DownloadRun::finished, this, &DownloadDialog::showReport);
    m_status->setText(tr("Reading the drive's values to compare them with the file..."));
}

void DownloadDialog::showReading(int done, int total, const QString &what)
{
    m_progress->setRange(0, std::max(1, total));
    m_progress->setValue(done);
    if (m_run->stage() == DownloadRun::Stage::Writing)
        m_status->setText(tr("Writing to the drive: %1").arg(what));
}

void DownloadDialog::showPlan(const DownloadPlan &plan)
{
    m_progress->hide();
    m_setRow->show();
    m_list->show();
    m_list->clear();
    for (const DownloadPlan::Line &line : plan.lines(m_run->drive())) {
        auto *item = new QTreeWidgetItem(QStringList{ line.id, line.name, line.sets, line.now,
                                                      line.then,
                                                      line.always ? tr("always written")
                                                                  : QString() });
        for (int column = 0; column < Columns; ++column)
            item->setToolTip(column, item->text(column));
        m_list->addTopLevelItem(item);
    }
    for (const DownloadSkip &skip : plan.skipped) {
        auto *item = new QTreeWidgetItem(
            QStringList{ skip.id, skip.name, QString(), QString(), QString(),
                         tr("left: %1").arg(skip.reason) });
        for (int column = 0; column < Columns; ++column) {
            item->setForeground(column, palette().brush(QPalette::Disabled, QPalette::Text));
            item->setToolTip(column, item->text(column));
        }
        m_list->addTopLevelItem(item);
    }
    QStringList problems;
    for (const QString &problem : plan.problems)
        problems << QStringLiteral("<li>%1</li>").arg(problem.toHtmlEscaped());
    m_problems->setVisible(!problems.isEmpty());
    m_problems->setText(tr("<b>The file does not fit the drive:</b><ul>%1</ul>")
                            .arg(problems.join(QString())));
    m_force->setVisible(!plan.problems.isEmpty());

    fitValueColumns();

    const int values = plan.valueCount();
    m_summary->setText(plan.summary() + QLatin1Char('.'));
    m_status->setText(plan.isRefused()
                          ? tr("Nothing will be written unless you overrule the checks.")
                          : values ? tr("Look at what will be written, then write it.")
                                   : tr("The drive holds the file's values already."));
    m_write->setText(tr("&Write %n Value(s)", nullptr, values));
    m_write->setEnabled(values > 0 && !plan.isRefused());
    if (m_write->isEnabled())
        m_write->setDefault(true);
    layout()->activate(); // the button's new text takes its room at once
}

void DownloadDialog::fitValueColumns()
{
    // Each column as wide as its widest text, the values and notes at most a fifth of the
    // dialog, so that every column stays in view; where the names would be cut, the values and
    // notes give up room for them first, down to 100 pixels each (a German name is long).
    QHeaderView *header = m_list->header();
    const int fixed = header->sectionSize(Id) + header->sectionSize(Sets);
    const int forValues = m_list->viewport()->width() - fixed - static_cast<const QAbstractItemView *>(m_list)->sizeHintForColumn(Name);
    const int cap = std::clamp(forValues / 3, 100, std::max(100, width() / 5));
    for (const int column : { Now, Then, Note }) {
        header->setSectionResizeMode(column, QHeaderView::Interactive);
        m_list->resizeColumnToContents(column);
        header->resizeSection(column, std::min(cap, header->sectionSize(column)));
    }
}

void DownloadDialog::resizeEvent(QResizeEvent *event)
{
    QDialog::resizeEvent(event);
    if (m_list->isVisible())
        fitValueColumns();
}

void DownloadDialog::changeOptions()
{
    DownloadOptions options = m_run->options();
    options.force = m_force->isChecked();
    options.sets = 0;
    for (int set = 0; set < int(m_sets.size()); ++set) {
        if (m_sets[std::size_t(set)]->isChecked())
            options.sets |= quint8(1u << set);
    }
    m_run->setOptions(options);
}

void DownloadDialog::write()
{
    m_write->setEnabled(false);
    m_force->setEnabled(false);
    m_setRow->setEnabled(false);
    m_progress->setRange(0, std::max(1, int(m_run->plan().items.size())));
    m_progress->setValue(0);
    m_progress->show();
    m_buttons->button(QDialogButtonBox::Cancel)->setText(tr("&Stop"));
    m_status->setText(tr("Writing to the drive..."));
    m_run->write();
}

void DownloadDialog::showFailure(const QString &reason)
{
    m_progress->hide();
    m_status->setText(reason);
    m_write->hide();
    m_buttons->button(QDialogButtonBox::Cancel)->setText(tr("&Close"));
}

void DownloadDialog::showReport(const DownloadReport &report)
{
    m_progress->hide();
    m_list->hide();
    m_setRow->hide();
    m_force->hide();
    m_problems->hide();
    m_summary->hide();
    m_write->hide();
    m_report->setPlainText(report.text());
    m_report->show();
    m_status->setText(report.isComplete()
                          ? tr("Download finished: everything to write was written and read "
                               "back.")
                          : tr("The download did not write everything. The report says what "
                               "the drive holds."));
    m_buttons->button(QDialogButtonBox::Cancel)->setText(tr("&Close"));
    // A value sent without an answer (the link cut) may have reached the drive as well.
    if (!report.written.isEmpty() || !report.refused.isEmpty() || !report.unknown.isEmpty())
        emit wrote();
}

void DownloadDialog::reject()
{
    switch (m_run->stage()) {
    case DownloadRun::Stage::Writing:
        // What is on its way is written all the same; the report follows.
        m_buttons->button(QDialogButtonBox::Cancel)->setEnabled(false);
        m_status->setText(tr("Stopping after the value on its way..."));
        m_run->stop();
        return;
    case DownloadRun::Stage::Reading:
        m_run->stop();
        break;
    default:
        break;
    }
    QDialog::reject();
}

} // namespace DriveDesk
