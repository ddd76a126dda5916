#pragma once

#include "ValueEditor.h"

#include <QFrame>
#include <QList>
#include <QRect>

class QComboBox;
class QLabel;

namespace DriveDesk {

// A bit-field parameter (several plaintext definitions, each over its own bits) edited in a
// popup with room: what is edited, then one row per definition with texts (its description and
// a combo box of its texts), the value the fields compose, OK and Cancel. The value is composed
// by Plaintexts::withField; bits no definition with texts covers keep their starting value.
// Tab moves between the fields. The ParameterDelegate writes on Enter or accepted() and writes
// nothing on Escape, rejected() or when the popup closes otherwise (a click elsewhere).
class BitFieldEditor : public QFrame, public ValueEditor
{
    Q_OBJECT
public:
    // `parent` owns the popup; it is not placed within it.
    explicit BitFieldEditor(const ParameterFormat &format, QWidget *parent = nullptr);

    // The parameter and set being edited, shown at the top.
    void setTitle(const QString &title);
    // Opens at the top left of `cell` (global coordinates), at least as wide as the cell and
    // as large as its content, moved to stay on the cell's screen.
    void placeAt(const QRect &cell);

    // One combo box per definition with texts, in definition order, each with its label.
    const QList<QComboBox *> &fields() const { return m_fields; }
    const QList<QLabel *> &labels() const { return m_labels; }

signals:
    void accepted();
    void rejected();

protected:
    void setRawValue(qint32 raw) override;
    std::optional<qint32> editedValue(QString *problem) const override;

private:
    void showComposedValue();

    QLabel *m_title = nullptr;
    QLabel *m_composed = nullptr;
    QList<QComboBox *> m_fields;
    QList<QLabel *> m_labels;
    QList<qsizetype> m_definitions; // the definition index of each field
    qint32 m_start = 0;
    QRect m_cell; // where it was placed
};

} // namespace DriveDesk
