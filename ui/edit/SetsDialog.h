#pragma once

#include <QDialog>

#include <array>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;

namespace DriveDesk {

// Chooses parameter sets: the sets a value is written to (check boxes, all or none), or the
// source and target of a set copy. OK stays disabled until the choice makes sense.
class SetsDialog : public QDialog
{
    Q_OBJECT
public:
    enum class Mode : quint8 { ChooseSets, CopySet };

    explicit SetsDialog(Mode mode, QWidget *parent = nullptr);

    Mode mode() const { return m_mode; }
    // What the choice is for, e.g. "Write 50.00 Hz to oP.10 in:".
    void setPrompt(const QString &text);
    // Marks the active set in the labels; -1 marks none.
    void setActiveSet(int set);

    // ChooseSets: bit n for set n.
    quint8 setMask() const;
    void setSetMask(quint8 mask);
    // CopySet.
    int fromSet() const;
    int toSet() const;
    void setCopy(int fromSet, int toSet);

private:
    QString setLabel(int set) const;
    void updateLabels();
    void updateOk();

    Mode m_mode = Mode::ChooseSets;
    int m_activeSet = -1;
    QLabel *m_prompt = nullptr;
    std::array<QCheckBox *, 8> m_sets {};
    QComboBox *m_from = nullptr;
    QComboBox *m_to = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace DriveDesk
