#include "ParameterDelegate.h"

#include "HexValueEdit.h"
#include "PlaintextEditors.h"
#include "ScaledSpinBox.h"

#include "model/ParameterModel.h"

#include <QKeyEvent>
#include <QPersistentModelIndex>
#include <QToolTip>

namespace DriveDesk {

namespace {

constexpr char kIndexProperty[] = "drivedeskIndex";

ValueEditor *valueEditor(QObject *editor)
{
    return dynamic_cast<ValueEditor *>(editor);
}

QModelIndex editedIndex(const QWidget *editor)
{
    return editor->property(kIndexProperty).value<QPersistentModelIndex>();
}

} // namespace

ParameterDelegate::ParameterDelegate(QObject *parent)
    : QStyledItemDelegate(parent)
{ }

QWidget *ParameterDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                                         const QModelIndex &index) const
{
    const QVariant description = index.data(ParameterModel::DescriptionRole);
    if (!description.canConvert<ParameterDescription>()
        || index.data(ParameterModel::SetRole).toInt() < 0
        || !index.data(ParameterModel::EditableRole).toBool()) {
        return QStyledItemDelegate::createEditor(parent, option, index);
    }

    ParameterFormat format(description.value<ParameterDescription>());
    // Raw values in the table, or a scaling nothing can be converted by: edit raw integers.
    if (index.data(ParameterModel::RawModeRole).toBool()
        || (!format.isHexadecimal() && !format.scaling().isValid())) {
        format = format.rawFormat();
    }

    QWidget *editor = nullptr;
    if (!format.isRaw() && format.isBitField())
        editor = new BitFieldEditor(format, parent);
    else if (!format.isRaw() && !format.plaintexts().isEmpty())
        editor = new PlaintextComboBox(format, parent);
    else if (format.isHexadecimal())
        editor = new HexValueEdit(format, parent);
    else
        editor = new ScaledSpinBox(format, parent);
    editor->setProperty(kIndexProperty, QVariant::fromValue(QPersistentModelIndex(index)));
    return editor;
}

void ParameterDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    ValueEditor *value = valueEditor(editor);
    if (!value) {
        QStyledItemDelegate::setEditorData(editor, index);
        return;
    }
    // Edit role: the value shown, or the default where none was read.
    value->start(index.data(Qt::EditRole).toInt());
}

void ParameterDelegate::setModelData(QWidget *editor, QAbstractItemModel *model,
                                     const QModelIndex &index) const
{
    const ValueEditor *value = valueEditor(editor);
    if (!value) {
        QStyledItemDelegate::setModelData(editor, model, index);
        return;
    }
    QString problem;
    const std::optional<qint32> raw = value->rawValue(&problem);
    if (!raw) {
        emit editRefused(index, problem);
        return;
    }
    if (raw == value->initialValue())
        return;
    if (!model->setData(index, *raw, Qt::EditRole))
        emit editRefused(index, tr("this parameter cannot be changed now"));
}

void ParameterDelegate::updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                                             const QModelIndex &index) const
{
    if (qobject_cast<BitFieldEditor *>(editor)) {
        // One combo box per field rarely fits the cell: grow to the right.
        QRect rect = option.rect;
        rect.setWidth(std::max(rect.width(), editor->sizeHint().width()));
        editor->setGeometry(rect);
        return;
    }
    QStyledItemDelegate::updateEditorGeometry(editor, option, index);
}

bool ParameterDelegate::eventFilter(QObject *object, QEvent *event)
{
    auto *editor = qobject_cast<QWidget *>(object);
    const ValueEditor *value = valueEditor(object);
    if (editor && value && event->type() == QEvent::KeyPress) {
        switch (static_cast<QKeyEvent *>(event)->key()) {
        case Qt::Key_Return:
        case Qt::Key_Enter:
        case Qt::Key_Tab:
        case Qt::Key_Backtab: {
            QString problem;
            if (value->rawValue(&problem))
                break;
            QToolTip::showText(editor->mapToGlobal(QPoint(0, editor->height())), problem, editor);
            emit editRefused(editedIndex(editor), problem);
            return true;
        }
        default:
            break;
        }
    }
    return QStyledItemDelegate::eventFilter(object, event);
}

} // namespace DriveDesk
