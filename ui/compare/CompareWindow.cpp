// CompareWindow: its sides, filters and table, and what they show.
#include "CompareWindow.h"

#include "CompareHost.h"
#include "ComparisonFilterModel.h"
#include "ComparisonModel.h"

#include "frame/FrameSupport.h"
#include "model/ParameterModel.h"
#include "parameters/ParameterComparison.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTreeView>
#include <QVBoxLayout>

namespace DriveDesk {

namespace {

constexpr ComparisonRow::State kStates[] = {
    ComparisonRow::State::Equal,   ComparisonRow::State::Different,
    ComparisonRow::State::OnlyInA, ComparisonRow::State::OnlyInB,
    ComparisonRow::State::ReadOnly, ComparisonRow::State::NotASetting,
};

} // namespace

CompareWindow::CompareWindow(CompareHost *host, QWidget *parent)
    : QWidget(parent, Qt::Window)
    , m_host(host)
{
    setObjectName(QStringLiteral("compareWindow"));
    setWindowTitle(tr("Compare Parameters - DriveDesk"));
    m_model = new ComparisonModel(this);
    m_filter = new ComparisonFilterModel(this);
    m_filter->setSourceModel(m_model);

    m_setAgainstSet = new QCheckBox(tr("Compare one &set of A with one set of B"), this);
    m_setAgainstSet->setObjectName(QStringLiteral("setAgainstSet"));
    m_setAgainstSet->setToolTip(
        tr("Only the set-programmable parameters, in the sets chosen on each side. Choose "
           "\"A itself\" for B to compare two sets of one drive or file."));
    m_compareButton = new QPushButton(tr("&Compare"), this);
    m_compareButton->setObjectName(QStringLiteral("compareButton"));
    m_compareButton->setDefault(true);
    connect(m_compareButton, &QPushButton::clicked, this, [this] { compare(); });

    auto *sides = new QVBoxLayout;
    sides->addWidget(makeSideRow(true));
    sides->addWidget(makeSideRow(false));
    auto *compareRow = new QHBoxLayout;
    compareRow->addWidget(m_setAgainstSet);
    compareRow->addStretch();
    compareRow->addWidget(m_compareButton);
    sides->addLayout(compareRow);
    connect(m_setAgainstSet, &QCheckBox::toggled, this, &CompareWindow::updateSideWidgets);

    m_view = new QTreeView(this);
    m_view->setObjectName(QStringLiteral("comparisonView"));
    m_view->setModel(m_filter);
    m_view->setUniformRowHeights(true);
    m_view->setAlternatingRowColors(true);
    m_view->setSortingEnabled(true);
    m_view->sortByColumn(ComparisonModel::IdColumn, Qt::AscendingOrder);
    m_view->setItemsExpandable(false);
    m_view->setRootIsDecorated(false);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->header()->setStretchLastSection(true);
    m_view->header()->resizeSection(ComparisonModel::IdColumn, 110);
    m_view->header()->resizeSection(ComparisonModel::NameColumn, 220);
    m_view->header()->resizeSection(ComparisonModel::SetColumn, 50);
    m_view->header()->resizeSection(ComparisonModel::AColumn, 170);
    m_view->header()->resizeSection(ComparisonModel::BColumn, 170);
    connect(m_filter, &QAbstractItemModel::modelReset, this, [this] { expandGroups(); });
    connect(m_filter, &QAbstractItemModel::layoutChanged, this, [this] { expandGroups(); });
    connect(m_filter, &QAbstractItemModel::rowsInserted, this, [this] { expandGroups(); });
    connect(m_filter, &QAbstractItemModel::rowsRemoved, this, &CompareWindow::updateCounts);

    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("compareSummary"));
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("compareMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_chooseShownButton = new QPushButton(tr("C&hoose Shown"), this);
    m_chooseShownButton->setObjectName(QStringLiteral("chooseShownButton"));
    m_chooseShownButton->setToolTip(tr("Tick every row shown whose value can be written"));
    connect(m_chooseShownButton, &QPushButton::clicked, this, [this] {
        for (int g = 0; g < m_filter->rowCount(); ++g) {
            const QModelIndex group = m_filter->index(g, 0);
            for (int r = 0; r < m_filter->rowCount(group); ++r)
                m_model->setChosen(m_filter->mapToSource(m_filter->index(r, 0, group)), true);
        }
    });
    m_clearChoiceButton = new QPushButton(tr("C&lear Choice"), this);
    m_clearChoiceButton->setObjectName(QStringLiteral("clearChoiceButton"));
    connect(m_clearChoiceButton, &QPushButton::clicked, this, [this] {
        m_model->clearChosen();
    });
    m_writeA = new QPushButton(this);
    m_writeA->setObjectName(QStringLiteral("writeToAButton"));
    connect(m_writeA, &QPushButton::clicked, this, [this] { writeChosen(true); });
    m_writeB = new QPushButton(this);
    m_writeB->setObjectName(QStringLiteral("writeToBButton"));
    connect(m_writeB, &QPushButton::clicked, this, [this] { writeChosen(false); });
    auto *closeButton = new QPushButton(tr("Close"), this);
    connect(closeButton, &QPushButton::clicked, this, &QWidget::close);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_chooseShownButton);
    buttons->addWidget(m_clearChoiceButton);
    buttons->addStretch();
    buttons->addWidget(m_writeA);
    buttons->addWidget(m_writeB);
    buttons->addWidget(closeButton);
    connect(m_model, &ComparisonModel::chosenChanged, this, [this] {
        updateWriteButtons();
        updateCounts();
    });

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(sides);
    layout->addWidget(makeFilterRow());
    layout->addWidget(m_view, 1);
    layout->addWidget(m_summary);
    layout->addWidget(m_message);
    layout->addLayout(buttons);

    auto *find = new QAction(this);
    find->setShortcut(QKeySequence::Find);
    find->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(find, &QAction::triggered, this, [this] {
        m_searchEdit->setFocus(Qt::ShortcutFocusReason);
        m_searchEdit->selectAll();
    });
    addAction(find);

    resize(1100, 700);
    updateSources();
    // A first guess: the drive or the file shown against a file to pick.
    if (m_host && m_host->hasDrive())
        setSide(true, Source::Drive);
    else if (m_host && !m_host->shownFilePath().isEmpty())
        setSide(true, Source::ShownFile);
    setSide(false, Source::File);
    updateCounts();
    updateWriteButtons();
}

QWidget *CompareWindow::makeSideRow(bool a)
{
    SideWidgets &side = a ? m_sideA : m_sideB;
    const QString name = a ? QStringLiteral("A") : QStringLiteral("B");
    auto *row = new QWidget(this);
    auto *label = new QLabel(a ? tr("Side &A:") : tr("Side &B:"), row);
    side.source = new QComboBox(row);
    side.source->setObjectName(QStringLiteral("source%1").arg(name));
    side.source->addItem(tr("The drive"), int(Source::Drive));
    side.source->addItem(tr("The file shown in the window"), int(Source::ShownFile));
    side.source->addItem(tr("A file"), int(Source::File));
    if (!a) {
        side.source->addItem(tr("Defaults of A"), int(Source::Defaults));
        side.source->addItem(tr("A itself (another set)"), int(Source::SameAsA));
    }
    label->setBuddy(side.source);
    side.path = new QLineEdit(row);
    side.path->setObjectName(QStringLiteral("path%1").arg(name));
    side.path->setPlaceholderText(tr("Parameter file (*.json)"));
    side.path->setClearButtonEnabled(true);
    side.browse = new QPushButton(tr("Browse..."), row);
    side.browse->setObjectName(QStringLiteral("browse%1").arg(name));
    connect(side.browse, &QPushButton::clicked, this, [this, a] { chooseFile(a); });
    auto *setLabel = new QLabel(tr("Set:"), row);
    side.set = new QSpinBox(row);
    side.set->setObjectName(QStringLiteral("set%1").arg(name));
    side.set->setRange(0, kParameterSets - 1);
    side.set->setValue(a ? 0 : 1);
    setLabel->setBuddy(side.set);
    connect(side.source, &QComboBox::currentIndexChanged, this, &CompareWindow::updateSideWidgets);

    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(label);
    layout->addWidget(side.source);
    layout->addWidget(side.path, 1);
    layout->addWidget(side.browse);
    layout->addWidget(setLabel);
    layout->addWidget(side.set);
    return row;
}

QWidget *CompareWindow::makeFilterRow()
{
    auto *row = new QWidget(this);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(tr("Show:"), row));
    for (std::size_t i = 0; i < std::size(kStates); ++i) {
        const ComparisonRow::State state = kStates[i];
        auto *box = new QCheckBox(row);
        box->setObjectName(QStringLiteral("showState%1").arg(int(state)));
        box->setChecked(m_filter->isStateShown(state));
        if (state == ComparisonRow::State::NotASetting)
            box->setToolTip(tr("Live and read-only values and parameters a parameter list "
                               "leaves out: never counted as a difference"));
        connect(box, &QCheckBox::toggled, this,
                [this, state](bool on) { m_filter->setStateShown(state, on); });
        m_stateBoxes[i] = box;
        layout->addWidget(box);
    }
    m_groupBox = new QComboBox(row);
    m_groupBox->setObjectName(QStringLiteral("groupFilter"));
    m_groupBox->addItem(tr("All groups"), QString());
    connect(m_groupBox, &QComboBox::currentIndexChanged, this,
            [this] { m_filter->setGroup(m_groupBox->currentData().toString()); });
    auto *groupLabel = new QLabel(tr("&Group:"), row);
    groupLabel->setBuddy(m_groupBox);
    m_searchEdit = new QLineEdit(row);
    m_searchEdit->setObjectName(QStringLiteral("compareSearch"));
    m_searchEdit->setPlaceholderText(tr("Search id, name or value"));
    m_searchEdit->setClearButtonEnabled(true);
    // Room for a parameter id and a word in every language, however long the filters' labels.
    m_searchEdit->setMinimumWidth(m_searchEdit->fontMetrics().horizontalAdvance(QLatin1Char('x')) * 18);
    connect(m_searchEdit, &QLineEdit::textChanged, m_filter,
            &ComparisonFilterModel::setFilterText);
    auto *searchLabel = new QLabel(tr("Sea&rch:"), row);
    searchLabel->setBuddy(m_searchEdit);
    m_chosenOnlyBox = new QCheckBox(tr("Chosen onl&y"), row);
    m_chosenOnlyBox->setObjectName(QStringLiteral("chosenOnly"));
    m_chosenOnlyBox->setToolTip(tr("Show only the rows ticked to be written: a last look"));
    connect(m_chosenOnlyBox, &QCheckBox::toggled, m_filter, &ComparisonFilterModel::setChosenOnly);
    m_rawBox = new QCheckBox(tr("Ra&w values"), row);
    m_rawBox->setObjectName(QStringLiteral("rawValues"));
    connect(m_rawBox, &QCheckBox::toggled, m_model, &ComparisonModel::setShowRawValues);
    layout->addSpacing(12);
    layout->addWidget(groupLabel);
    layout->addWidget(m_groupBox);
    layout->addWidget(searchLabel);
    layout->addWidget(m_searchEdit, 1);
    layout->addWidget(m_chosenOnlyBox);
    layout->addWidget(m_rawBox);
    return row;
}

void CompareWindow::setSide(bool a, Source source, const QString &path)
{
    SideWidgets &side = a ? m_sideA : m_sideB;
    side.source->setCurrentIndex(side.source->findData(int(source)));
    if (source == Source::File)
        side.path->setText(path);
    updateSideWidgets();
}

void CompareWindow::setReading(bool a, const QString &path, const QString &name)
{
    setSide(a, Source::File, path);
    SideWidgets &side = a ? m_sideA : m_sideB;
    side.readingPath = path;
    side.readingName = name;
}

void CompareWindow::setSets(int setA, int setB)
{
    m_setAgainstSet->setChecked(setA >= 0 && setB >= 0);
    if (setA >= 0)
        m_sideA.set->setValue(setA);
    if (setB >= 0)
        m_sideB.set->setValue(setB);
}

CompareWindow::Source CompareWindow::sourceOf(bool a) const
{
    return Source((a ? m_sideA : m_sideB).source->currentData().toInt());
}

void CompareWindow::updateSources()
{
    const bool drive = m_host && m_host->hasDrive();
    const bool file = m_host && !m_host->shownFilePath().isEmpty();
    for (SideWidgets *side : { &m_sideA, &m_sideB }) {
        auto *items = qobject_cast<QStandardItemModel *>(side->source->model());
        items->item(side->source->findData(int(Source::Drive)))->setEnabled(drive);
        items->item(side->source->findData(int(Source::ShownFile)))->setEnabled(file);
        const Source now = Source(side->source->currentData().toInt());
        if ((now == Source::Drive && !drive) || (now == Source::ShownFile && !file))
            side->source->setCurrentIndex(side->source->findData(int(Source::File)));
    }
    updateSideWidgets();
    updateWriteButtons();
}

void CompareWindow::updateSideWidgets()
{
    for (bool a : { true, false }) {
        SideWidgets &side = a ? m_sideA : m_sideB;
        const bool file = sourceOf(a) == Source::File;
        side.path->setEnabled(file);
        side.browse->setEnabled(file);
        side.set->setEnabled(m_setAgainstSet->isChecked());
    }
}

void CompareWindow::chooseFile(bool a)
{
    m_host->chooseFile(a ? tr("Side A: Parameter File") : tr("Side B: Parameter File"),
                       [this, a](const QString &path) { setSide(a, Source::File, path); });
}

void CompareWindow::expandGroups()
{
    m_view->expandAll();
    for (int g = 0; g < m_filter->rowCount(); ++g)
        m_view->setFirstColumnSpanned(g, {}, true);
    updateCounts();
}

void CompareWindow::updateCounts()
{
    const ComparisonTable &table = m_model->comparison();
    const QString names[] = { tr("&Equal (%1)"), tr("&Different (%1)"), tr("Only in A (%1)"),
                              tr("Only in B (%1)"), tr("Read-&only (%1)"),
                              tr("&Not settings (%1)") };
    for (std::size_t i = 0; i < std::size(kStates); ++i)
        m_stateBoxes[i]->setText(names[i].arg(table.count(kStates[i])));
    int shown = 0;
    for (int g = 0; g < m_filter->rowCount(); ++g)
        shown += m_filter->rowCount(m_filter->index(g, 0));
    m_summary->setText(tr("%1 of %n value(s) shown, %2 chosen.", nullptr, int(table.rows.size()))
                           .arg(shown)
                           .arg(m_model->chosenRows().size()));
}

void CompareWindow::showMessage(const QString &text)
{
    m_message->setText(text);
}

QString CompareWindow::message() const
{
    return m_message->text();
}

void CompareWindow::showRefusals(const QString &text, const QStringList &refusals)
{
    showMessage(text);
    if (refusals.isEmpty())
        return;
    auto *box = new QMessageBox(QMessageBox::Warning, tr("Compare Parameters"), text,
                                QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("compareRefusals"));
    box->setInformativeText(
        tr("%n value(s) were not written:", nullptr, int(refusals.size())));
    box->setDetailedText(refusals.join(QLatin1Char('\n')));
    openDialog(box);
}

} // namespace DriveDesk
