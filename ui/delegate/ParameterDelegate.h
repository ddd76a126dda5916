#pragma once

#include <QStyledItemDelegate>

namespace DriveDesk {

// Edits the value cells of a ParameterModel (directly or through proxies) with the editor the
// parameter's metadata calls for: a combo box of plaintexts (written as soon as a text is
// picked), a popup with a labelled combo box per field of a bit-field (written on Enter or OK),
// a hexadecimal line edit, or a spin box over raw steps with decimals and unit. A value the
// parameter cannot hold exactly or that lies outside its limits is refused with the reason
// (editRefused) and not written; a value left unchanged is not written either.
class ParameterDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    explicit ParameterDelegate(QObject *parent = nullptr);

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model,
                      const QModelIndex &index) const override;
    void updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                              const QModelIndex &index) const override;

signals:
    // For the status bar. `index` is of the view's model.
    void editRefused(const QModelIndex &index, const QString &reason) const;

protected:
    // Enter or Tab on a value that cannot be written keeps the editor open with the reason.
    // A bit-field popup that closes without Enter or OK writes nothing.
    bool eventFilter(QObject *object, QEvent *event) override;

private:
    // Writes the editor's value and closes it, or keeps it open with the reason.
    void commitAndClose(QWidget *editor);
    // False, with the reason shown at the editor and emitted, when its value cannot be written.
    bool checkWritable(QWidget *editor);
};

} // namespace DriveDesk
