#include "ParameterDelegate.h"

#include "BitFieldEditor.h"
#include "HexValueEdit.h"
#include "PlaintextEditors.h"
#include "ScaledSpinBox.h"

#include "model/ParameterModel.h"

#include <QAbstractItemView>
#include <QKeyEvent>
#include <QPersistentModelIndex>
#include <QPointer>
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

// What a bit-field popup edits: "uF.06 Energy saving mode, Set 1".
QString editorTitle(const QModelIndex &index)
{
    const QString id = index.siblingAtColumn(ParameterModel::IdColumn).data().toString();
    const QString name = index.siblingAtColumn(ParameterModel::NameColumn).data().toString();
    const QString parameter = QStringList { id, name }.join(QLatin1Char(' ')).trimmed();
    const QString set = index.model()->headerData(index.column(), Qt::Horizontal).toString();
    if (parameter.isEmpty() || set.isEmpty())
        return parameter + set;
    return ParameterDelegate::tr("%1, %2", "parameter, set").arg(parameter, set);
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

    // The editor's signals end the edit: the delegate's own slots, though createEditor is const.
    auto *self = const_cast<ParameterDelegate *>(this);
    QWidget *editor = nullptr;
    if (!format.isRaw() && format.isBitField()) {
        // A popup window owned by the view, not a child of its viewport: it needs more room
        // than the cell and may reach beyond the view.
        auto *bitField = new BitFieldEditor(format, parent->parentWidget() ? parent->parentWidget()
                                                                           : parent);
        bitField->setTitle(editorTitle(index));
        connect(bitField, &BitFieldEditor::accepted, self,
                [self, bitField] { self->commitAndClose(bitField); });
        connect(bitField, &BitFieldEditor::rejected, self, [self, bitField] {
            emit self->closeEditor(bitField, QAbstractItemDelegate::RevertModelCache);
        });
        editor = bitField;
    } else if (!format.isRaw() && !format.plaintexts().isEmpty()) {
        auto *combo = new PlaintextComboBox(format, parent);
        connect(combo, &PlaintextComboBox::picked, self,
                [self, combo] { self->commitAndClose(combo); });
        editor = combo;
    } else if (format.isHexadecimal())
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
    if (auto *bitField = qobject_cast<BitFieldEditor *>(editor)) {
        // option.rect is in the viewport's coordinates; the popup is a window of its own.
        const auto *view = qobject_cast<const QAbstractItemView *>(option.widget);
        const QWidget *area = view ? view->viewport() : editor->parentWidget();
        bitField->placeAt(QRect(area->mapToGlobal(option.rect.topLeft()), option.rect.size()));
        return;
    }
    QStyledItemDelegate::updateEditorGeometry(editor, option, index);
}

bool ParameterDelegate::checkWritable(QWidget *editor)
{
    const ValueEditor *value = valueEditor(editor);
    QString problem;
    if (!value || value->rawValue(&problem))
        return true;
    QToolTip::showText(editor->mapToGlobal(QPoint(0, editor->height())), problem, editor);
    emit editRefused(editedIndex(editor), problem);
    return false;
}

void ParameterDelegate::commitAndClose(QWidget *editor)
{
    if (!checkWritable(editor))
        return;
    emit commitData(editor);
    emit closeEditor(editor, QAbstractItemDelegate::NoHint);
}

bool ParameterDelegate::eventFilter(QObject *object, QEvent *event)
{
    auto *editor = qobject_cast<QWidget *>(object);
    if (!editor || !valueEditor(object))
        return QStyledItemDelegate::eventFilter(object, event);

    if (event->type() == QEvent::KeyPress) {
        switch (static_cast<QKeyEvent *>(event)->key()) {
        case Qt::Key_Return:
        case Qt::Key_Enter:
        case Qt::Key_Tab:
        case Qt::Key_Backtab:
            if (!checkWritable(editor))
                return true;
            break;
        default:
            break;
        }
    } else if (event->type() == QEvent::Hide && qobject_cast<BitFieldEditor *>(editor)) {
        // The popup closed by a click elsewhere (or the cell scrolled away): the base class
        // would write what it holds. An edit ended by Enter or OK no longer has this filter
        // when the view hides its editor, so whatever still sees the popup hide reverts.
        // Queued: the view may be tearing the popup down with itself.
        QMetaObject::invokeMethod(
            this,
            [this, popup = QPointer<QWidget>(editor)] {
                if (popup && popup->isHidden())
                    emit closeEditor(popup, QAbstractItemDelegate::RevertModelCache);
            },
            Qt::QueuedConnection);
        return false;
    }
    return QStyledItemDelegate::eventFilter(object, event);
}

} // namespace DriveDesk
