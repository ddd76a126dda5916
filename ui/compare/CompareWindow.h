#pragma once

#include "parameters/ChosenValues.h"
#include "parameters/DriveDescription.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTreeView;

namespace DriveDesk {

class CompareHost;
class ComparisonFilterModel;
class ComparisonModel;

// The compare window: two sides (the drive, the file the window shows, a file, A's defaults,
// or A itself for one set against another), every value of both in a table with its state,
// filters by state, group and the parameter table's search, and the values a user ticks
// written into one side: a file directly (saved atomically), the file shown through the
// window's edits, the drive by handing a selection to the window's download. Non-modal: it
// never waits for a dialog. `host` may be nullptr: then only files and defaults are offered.
class CompareWindow : public QWidget
{
    Q_OBJECT
public:
    // Where a side comes from; Defaults and SameAsA are B's only.
    enum class Source { Drive, ShownFile, File, Defaults, SameAsA };

    explicit CompareWindow(CompareHost *host, QWidget *parent = nullptr);

    // Chooses a side without comparing; `path` for Source::File.
    void setSide(bool a, Source source, const QString &path = {});
    // A side that is a drive read into a file of its own for this comparison (the plant's
    // Compare): named `name`, and never written, since writing into that file would change
    // neither the drive nor its backup. Choosing another file for the side ends it.
    void setReading(bool a, const QString &path, const QString &name);
    // One set of A against one set of B; -1 for set by set.
    void setSets(int setA, int setB);
    // Reads both sides again and shows their comparison; false with the reason shown when a
    // side cannot be read (then the table is left as it was).
    bool compare();
    // The host's drive or file came or went: the choices follow.
    void updateSources();

    ComparisonModel *comparisonModel() const { return m_model; }
    ComparisonFilterModel *filterModel() const { return m_filter; }
    QTreeView *view() const { return m_view; }
    // The last result or refusal in words, as the window shows it.
    QString message() const;

    // Writes the chosen values into side A (`toA`) or B, as the button of that side does.
    void writeChosen(bool toA);
    // The window has read the drive's values again. After chosen values went to the drive (the
    // download writes them, then the window reads the drive), compares again: what was
    // written is equal now and no longer chosen.
    void driveReadAgain();

private:
    struct SideWidgets
    {
        QComboBox *source = nullptr;
        QLineEdit *path = nullptr;
        QPushButton *browse = nullptr;
        QSpinBox *set = nullptr;
        QString readingPath; // setReading(): the file that holds the drive read, and its name
        QString readingName;
    };
    // A side as read for a comparison.
    struct Side
    {
        Source source = Source::File;
        QString path; // of a file; the file shown's too
        QString name; // "b.json", "the drive", "defaults of a.json"
        DriveDescription description; // what is compared
        DriveDescription origin; // the whole description it comes from, for a selection
        bool writable = true; // defaults are not, nor a reading of a drive
        bool reading = false; // setReading()
    };

    QWidget *makeSideRow(bool a);
    QWidget *makeFilterRow();
    void chooseFile(bool a);
    Source sourceOf(bool a) const;
    // The side as it is now; nothing, with the reason, when it cannot be read.
    std::optional<Side> readSide(bool a, const Side *sideA, QString *error) const;
    void updateSideWidgets();
    void updateCounts();
    void updateWriteButtons();
    void expandGroups();
    void showMessage(const QString &text);
    void showRefusals(const QString &text, const QStringList &refusals);
    void writeToFile(const Side &target, const QList<ChosenValue> &values);

    CompareHost *m_host = nullptr;
    SideWidgets m_sideA;
    SideWidgets m_sideB;
    QCheckBox *m_setAgainstSet = nullptr;
    QPushButton *m_compareButton = nullptr;
    QCheckBox *m_stateBoxes[6] = {};
    QComboBox *m_groupBox = nullptr;
    QLineEdit *m_searchEdit = nullptr;
    QCheckBox *m_chosenOnlyBox = nullptr;
    QCheckBox *m_rawBox = nullptr;
    QTreeView *m_view = nullptr;
    QLabel *m_summary = nullptr;
    QLabel *m_message = nullptr;
    QPushButton *m_chooseShownButton = nullptr;
    QPushButton *m_clearChoiceButton = nullptr;
    QPushButton *m_writeA = nullptr;
    QPushButton *m_writeB = nullptr;
    ComparisonModel *m_model = nullptr;
    ComparisonFilterModel *m_filter = nullptr;
    std::optional<Side> m_a; // as last compared
    std::optional<Side> m_b;
    bool m_waitingForDrive = false; // values were handed to the download
};

} // namespace DriveDesk
