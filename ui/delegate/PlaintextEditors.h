#pragma once

#include "ValueEditor.h"

#include <QComboBox>
#include <QList>
#include <QWidget>

namespace DriveDesk {

// The texts of an enumeration (one plaintext definition) to choose from. Texts whose value lies
// outside the limits are shown but cannot be chosen; a starting value without a text is offered
// as it is, so that leaving the editor alone changes nothing.
class PlaintextComboBox : public QComboBox, public ValueEditor
{
    Q_OBJECT
public:
    explicit PlaintextComboBox(const ParameterFormat &format, QWidget *parent = nullptr);

protected:
    void setRawValue(qint32 raw) override;
    std::optional<qint32> editedValue(QString *problem) const override;
};

// A bit-field parameter (several plaintext definitions, each over its own bits): one combo box
// per definition, the value composed from their masks. Bits no definition with texts covers
// keep their starting value.
class BitFieldEditor : public QWidget, public ValueEditor
{
    Q_OBJECT
public:
    explicit BitFieldEditor(const ParameterFormat &format, QWidget *parent = nullptr);

    // One combo box per definition with texts, in definition order.
    const QList<QComboBox *> &fields() const { return m_fields; }

protected:
    void setRawValue(qint32 raw) override;
    std::optional<qint32> editedValue(QString *problem) const override;

private:
    QList<QComboBox *> m_fields;
    QList<PlaintextDefinition> m_definitions; // those with texts, one per field
    quint32 m_covered = 0;
    qint32 m_start = 0;
};

} // namespace DriveDesk
