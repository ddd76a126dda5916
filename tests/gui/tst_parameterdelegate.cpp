#include "../parameters/EditorSampleDrive.h"

#include "delegate/BitFieldEditor.h"
#include "delegate/HexValueEdit.h"
#include "delegate/ParameterDelegate.h"
#include "delegate/PlaintextEditors.h"
#include "delegate/ScaledSpinBox.h"
#include "model/ParameterFilterModel.h"
#include "model/ParameterModel.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>
#include <QTreeView>

#include <memory>

using namespace DriveDesk;
using namespace DriveDesk::EditorSample;

// Editing values in a real tree view: the editor each kind of parameter gets, and what reaches
// the model (valueEdited) or is refused with the reason. The view commits an editor's value
// from its event loop after Enter, hence QTRY_ for what follows a commit.
class TestParameterDelegate : public QObject
{
    Q_OBJECT
private:
    std::unique_ptr<ParameterModel> m_model;
    std::unique_ptr<ParameterFilterModel> m_filter;
    std::unique_ptr<ParameterDelegate> m_delegate;
    std::unique_ptr<QTreeView> m_view;

    QModelIndex viewIndex(quint16 address, int set = 0) const
    {
        return m_filter->mapFromSource(m_model->valueIndex(address, set));
    }

    QWidget *openEditor(quint16 address, int set = 0)
    {
        const QModelIndex index = viewIndex(address, set);
        m_view->setCurrentIndex(index);
        m_view->edit(index);
        return m_view->indexWidget(index);
    }

    static void typeOver(QWidget *editor, const QString &text)
    {
        editor->setFocus();
        QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(editor, text);
    }

private slots:
    void init()
    {
        m_model = std::make_unique<ParameterModel>();
        m_model->state()->setDescription(drive());
        // As the edit path does (ValueEdits::pending): the cells show pending once asked for.
        connect(m_model.get(), &ParameterModel::valueEdited, m_model->state(),
                &DriveState::markPending);
        m_filter = std::make_unique<ParameterFilterModel>();
        m_filter->setSourceModel(m_model.get());
        m_delegate = std::make_unique<ParameterDelegate>();
        m_view = std::make_unique<QTreeView>();
        m_view->setModel(m_filter.get());
        m_view->setItemDelegate(m_delegate.get());
        m_view->expandAll();
        m_view->resize(1400, 500);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    }

    void cleanup()
    {
        m_view.reset();
        m_delegate.reset();
        m_filter.reset();
        m_model.reset();
    }

    void spinBoxStepsRawStepsWithinTheLimits()
    {
        auto *spin = qobject_cast<ScaledSpinBox *>(openEditor(kMaxFrequency, 1));
        QVERIFY(spin);
        QCOMPARE(spin->minimum(), 0);
        QCOMPARE(spin->maximum(), 40000);
        QCOMPARE(spin->singleStep(), 1);
        QCOMPARE(spin->decimals(), 2);
        QCOMPARE(spin->suffix(), QStringLiteral(" Hz"));
        QCOMPARE(spin->text(), QStringLiteral("60.00 Hz")); // as the table shows it
        QCOMPARE(m_model->valueIndex(kMaxFrequency, 1).data().toString(), spin->text());

        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        QTest::keyClick(spin, Qt::Key_Up);
        QCOMPARE(spin->text(), QStringLiteral("60.01 Hz"));
        QTest::keyClick(spin, Qt::Key_Return);
        QTRY_COMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(0).value<quint16>(), kMaxFrequency);
        QCOMPARE(edited.at(0).at(1).value<quint8>(), quint8(0x02));
        QCOMPARE(edited.at(0).at(2).value<qint32>(), 6001);
        QCOMPARE(m_model->state()->editState(kMaxFrequency, 1), EditState::Pending);

        spin = qobject_cast<ScaledSpinBox *>(openEditor(kMaxFrequency, 0));
        QVERIFY(spin);
        spin->setValue(1);
        QTest::keyClick(spin, Qt::Key_Down);
        QCOMPARE(spin->text(), QStringLiteral("0.00 Hz"));
        QTest::keyClick(spin, Qt::Key_Down);
        QCOMPARE(spin->text(), QStringLiteral("0.00 Hz")); // never below the minimum
    }

    void typedValuesAreTakenOnlyWhenExact()
    {
        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        QSignalSpy refused(m_delegate.get(), &ParameterDelegate::editRefused);
        QWidget *editor = openEditor(kMaxFrequency, 2);
        QVERIFY(qobject_cast<ScaledSpinBox *>(editor));

        typeOver(editor, QStringLiteral("75.255"));
        QTest::keyClick(editor, Qt::Key_Return);
        QCOMPARE(edited.size(), 0);
        QCOMPARE(refused.size(), 1);
        QCOMPARE(refused.at(0).at(1).toString(),
                 QStringLiteral("75.255 Hz cannot be set exactly: the nearest value this "
                                "parameter can hold is 75.26 Hz"));
        QCOMPARE(m_view->indexWidget(viewIndex(kMaxFrequency, 2)), editor); // still open

        typeOver(editor, QStringLiteral("500"));
        QTest::keyClick(editor, Qt::Key_Return);
        QCOMPARE(refused.size(), 2);
        QCOMPARE(refused.at(1).at(1).toString(),
                 QStringLiteral("500.00 Hz is outside the limits 0.00 .. 400.00 Hz"));
        QCOMPARE(edited.size(), 0);

        typeOver(editor, QStringLiteral("75.25"));
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(2).value<qint32>(), 7525);
        QCOMPARE(m_model->valueIndex(kMaxFrequency, 2).data().toString(),
                 QStringLiteral("75.25 Hz"));
    }

    void anUnchangedValueIsNotWritten()
    {
        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        QWidget *editor = openEditor(kRampTime);
        QVERIFY(editor);
        // The drive reports a new value while the editor is open: what the user sees stays.
        m_model->state()->setValue(kRampTime, 0, 900);
        QCOMPARE(qobject_cast<ScaledSpinBox *>(editor)->text(), QStringLiteral("5.00 s"));
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_VERIFY(!m_view->indexWidget(viewIndex(kRampTime)));
        QCOMPARE(edited.size(), 0);
        QCOMPARE(m_model->state()->editState(kRampTime, 0), EditState::None);
    }

    void enumerationsGetAComboBoxOfTheirPlaintexts()
    {
        auto *combo = qobject_cast<PlaintextComboBox *>(openEditor(kSource));
        QVERIFY(combo);
        QCOMPARE(combo->count(), 4);
        QCOMPARE(combo->currentText(), QStringLiteral("analog"));
        QCOMPARE(combo->itemText(3), QStringLiteral("limited"));
        auto *items = qobject_cast<QStandardItemModel *>(combo->model());
        QVERIFY(items);
        QVERIFY(items->item(2)->isEnabled());
        QVERIFY(!items->item(3)->isEnabled()); // 3 is above the maximum 2
        QCOMPARE(items->item(3)->toolTip(), QStringLiteral("3 is outside the limits 0 .. 2"));

        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        combo->setCurrentIndex(2);
        QTest::keyClick(combo, Qt::Key_Return);
        QTRY_COMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(2).value<qint32>(), 2);
        QCOMPARE(m_model->valueIndex(kSource, 0).data().toString(), QStringLiteral("bus"));
    }

    void aPickedTextIsWrittenWithoutEnter()
    {
        auto *combo = qobject_cast<PlaintextComboBox *>(openEditor(kSource));
        QVERIFY(combo);
        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        combo->showPopup();
        QAbstractItemView *list = combo->view();
        QTRY_VERIFY(list->isVisible());
        const QRect bus = list->visualRect(list->model()->index(2, 0));
        QTest::mouseMove(list->viewport(), bus.center());
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, bus.center());
        QTRY_COMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(0).value<quint16>(), kSource);
        QCOMPARE(edited.at(0).at(2).value<qint32>(), 2);
        QTRY_VERIFY(!m_view->indexWidget(viewIndex(kSource))); // closed
        QCOMPARE(m_model->valueIndex(kSource, 0).data().toString(), QStringLiteral("bus"));
    }

    void steppingAClosedComboBoxWritesOnlyOnEnter()
    {
        auto *combo = qobject_cast<PlaintextComboBox *>(openEditor(kSource));
        QVERIFY(combo);
        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        QCOMPARE(combo->currentText(), QStringLiteral("analog"));
        QTest::keyClick(combo, Qt::Key_Down);
        QCOMPARE(combo->currentText(), QStringLiteral("bus"));
        QCOMPARE(edited.size(), 0);
        QCOMPARE(m_view->indexWidget(viewIndex(kSource)), combo);
        QTest::keyClick(combo, Qt::Key_Return);
        QTRY_COMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(2).value<qint32>(), 2);
    }

    void bitFieldsOpenAPopupWithALabelPerDefinition()
    {
        m_model->state()->setValue(kControl, 0, 0x0105); // bit 8 belongs to no definition
        const QModelIndex cell = viewIndex(kControl);
        auto *editor = qobject_cast<BitFieldEditor *>(openEditor(kControl));
        QVERIFY(editor);
        QTRY_VERIFY(editor->isVisible());
        QVERIFY(editor->isWindow()); // not clipped by the cell, nor by the view

        QCOMPARE(editor->labels().size(), 2);
        QCOMPARE(editor->fields().size(), 2);
        QCOMPARE(editor->labels().at(0)->text(), QStringLiteral("Direction:"));
        QCOMPARE(editor->labels().at(1)->text(), QStringLiteral("Release:"));
        QCOMPARE(editor->labels().at(0)->buddy(), editor->fields().at(0));
        QCOMPARE(editor->fields().at(0)->currentText(), QStringLiteral("forward"));
        QCOMPARE(editor->fields().at(1)->currentText(), QStringLiteral("released"));
        QVERIFY(editor->findChild<QLabel *>()->text().startsWith(QStringLiteral("Pn.05")));

        // Room for everything it holds, and more than the cell.
        const QRect cellRect = m_view->visualRect(cell);
        QVERIFY(editor->width() >= editor->sizeHint().width());
        QVERIFY(editor->width() > cellRect.width());
        QList<QWidget *> shown;
        for (QLabel *label : editor->findChildren<QLabel *>())
            shown << label;
        for (QComboBox *field : editor->fields())
            shown << field;
        for (QPushButton *button : editor->findChildren<QPushButton *>())
            shown << button;
        for (QWidget *widget : std::as_const(shown)) {
            if (widget->isHidden())
                continue;
            const QRect within(widget->mapTo(editor, QPoint(0, 0)), widget->size());
            QVERIFY2(editor->rect().contains(within), qPrintable(widget->objectName()));
            QVERIFY(widget->width() >= widget->sizeHint().width()
                    || (qobject_cast<QLabel *>(widget)
                        && qobject_cast<QLabel *>(widget)->wordWrap()));
            const int needed = widget->hasHeightForWidth() ? widget->heightForWidth(widget->width())
                                                           : widget->sizeHint().height();
            QVERIFY2(widget->height() >= needed,
                     qPrintable(QStringLiteral("%1 '%2': %3 < %4")
                                    .arg(QString::fromLatin1(widget->metaObject()->className()),
                                         widget->property("text").toString())
                                    .arg(widget->height())
                                    .arg(needed)));
        }
        // Opens where the cell is.
        QCOMPARE(editor->pos(), m_view->viewport()->mapToGlobal(cellRect.topLeft()));

        // Tab goes from field to field.
        QTRY_COMPARE(QApplication::focusWidget(), editor->fields().at(0));
        QTest::keyClick(editor->fields().at(0), Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), editor->fields().at(1));
        QCOMPARE(m_view->indexWidget(cell), editor);
    }

    void enterWritesTheComposedBitField()
    {
        m_model->state()->setValue(kControl, 0, 0x0105);
        auto *editor = qobject_cast<BitFieldEditor *>(openEditor(kControl));
        QVERIFY(editor);
        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        QComboBox *direction = editor->fields().at(0);
        QComboBox *release = editor->fields().at(1);
        direction->setCurrentIndex(direction->findText(QStringLiteral("reverse")));
        release->setCurrentIndex(release->findText(QStringLiteral("locked")));
        QVERIFY(editor->findChildren<QLabel *>().last()->text().contains(
            QStringLiteral("reverse | locked | other bits 0100h")));
        QCOMPARE(edited.size(), 0);
        QTest::keyClick(release, Qt::Key_Return);
        QTRY_COMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(0).value<quint16>(), kControl);
        QCOMPARE(edited.at(0).at(1).value<quint8>(), quint8(0x01));
        QCOMPARE(edited.at(0).at(2).value<qint32>(), 0x0102);
        QTRY_VERIFY(!m_view->indexWidget(viewIndex(kControl)));
        QCOMPARE(m_model->valueIndex(kControl, 0).data().toString(),
                 QStringLiteral("reverse | locked | other bits 0100h"));

        // OK writes as Enter does.
        editor = qobject_cast<BitFieldEditor *>(openEditor(kControl));
        QVERIFY(editor);
        editor->fields().at(0)->setCurrentIndex(0); // stop
        auto *buttons = editor->findChild<QDialogButtonBox *>();
        QVERIFY(buttons);
        QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
        QTRY_COMPARE(edited.size(), 2);
        QCOMPARE(edited.at(1).at(2).value<qint32>(), 0x0100);
    }

    void aBitFieldPopupClosedWithoutEnterWritesNothing()
    {
        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        auto pickReverse = [this](int set) {
            auto *editor = qobject_cast<BitFieldEditor *>(openEditor(kControl, set));
            if (editor)
                editor->fields().at(0)->setCurrentIndex(2);
            return editor;
        };

        BitFieldEditor *editor = pickReverse(0);
        QVERIFY(editor);
        QTest::keyClick(editor->fields().at(0), Qt::Key_Escape);
        QTRY_VERIFY(!m_view->indexWidget(viewIndex(kControl)));

        editor = pickReverse(0);
        QVERIFY(editor);
        QTest::mouseClick(editor->findChild<QDialogButtonBox *>()->button(
                              QDialogButtonBox::Cancel),
                          Qt::LeftButton);
        QTRY_VERIFY(!m_view->indexWidget(viewIndex(kControl)));

        editor = pickReverse(0);
        QVERIFY(editor);
        editor->close(); // as a click outside the popup closes it
        QTRY_VERIFY(!m_view->indexWidget(viewIndex(kControl)));

        QCOMPARE(m_model->state()->editState(kControl, 0), EditState::None);
        QCOMPARE(m_model->valueIndex(kControl, 0).data().toString(),
                 QStringLiteral("forward | released"));
        // An edit of another parameter is the one that must come, and alone: anything the three
        // closed popups had let through would have arrived before it.
        auto *spin = qobject_cast<ScaledSpinBox *>(openEditor(kMaxFrequency, 1));
        QVERIFY(spin);
        QTest::keyClick(spin, Qt::Key_Up);
        QTest::keyClick(spin, Qt::Key_Return);
        QTRY_COMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(0).value<quint16>(), kMaxFrequency);
    }

    void aBitFieldOutsideTheLimitsIsRefused()
    {
        // Below the minimum 0 already: left alone it may stay, changed it may not.
        m_model->state()->setValue(kControl, 0, qint32(0x80000005));
        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        QSignalSpy refused(m_delegate.get(), &ParameterDelegate::editRefused);
        auto *editor = qobject_cast<BitFieldEditor *>(openEditor(kControl));
        QVERIFY(editor);
        editor->fields().at(0)->setCurrentIndex(editor->fields().at(0)->findText(
            QStringLiteral("reverse")));
        QTest::keyClick(editor->fields().at(0), Qt::Key_Return);
        QCOMPARE(refused.size(), 1);
        QVERIFY(refused.at(0).at(1).toString().contains(QStringLiteral("outside the limits")));
        QCOMPARE(m_view->indexWidget(viewIndex(kControl)), editor); // still open
        QTest::keyClick(editor->fields().at(0), Qt::Key_Escape);
        QTRY_VERIFY(!m_view->indexWidget(viewIndex(kControl)));

        // An edit of another parameter is the one that must come, and alone: a write of the
        // refused value would have arrived before it.
        auto *spin = qobject_cast<ScaledSpinBox *>(openEditor(kMaxFrequency, 1));
        QVERIFY(spin);
        QTest::keyClick(spin, Qt::Key_Up);
        QTest::keyClick(spin, Qt::Key_Return);
        QTRY_COMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(0).value<quint16>(), kMaxFrequency);
        QCOMPARE(refused.size(), 1);
    }

    void hexadecimalParametersGetAHexLineEdit()
    {
        auto *edit = qobject_cast<HexValueEdit *>(openEditor(kErrorMask));
        QVERIFY(edit);
        QCOMPARE(edit->text(), QStringLiteral("00FFh"));
        QVERIFY(edit->validator());

        QSignalSpy edited(m_model.get(), &ParameterModel::valueEdited);
        QSignalSpy refused(m_delegate.get(), &ParameterDelegate::editRefused);
        typeOver(edit, QStringLiteral("0x1AG0")); // the validator drops the G
        QCOMPARE(edit->text(), QStringLiteral("0x1A0"));
        typeOver(edit, QStringLiteral("FFFF"));
        QTest::keyClick(edit, Qt::Key_Return);
        QCOMPARE(refused.size(), 1);
        QCOMPARE(refused.at(0).at(1).toString(),
                 QStringLiteral("FFFFh is outside the limits 0000h .. 0FFFh"));
        typeOver(edit, QStringLiteral("1a0h"));
        QTest::keyClick(edit, Qt::Key_Return);
        QTRY_COMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(2).value<qint32>(), 0x01A0);
        QCOMPARE(m_model->valueIndex(kErrorMask, 0).data().toString(), QStringLiteral("01A0h"));
    }

    void rawValuesAreEditedRaw()
    {
        m_model->setShowRawValues(true);
        auto *spin = qobject_cast<ScaledSpinBox *>(openEditor(kMaxFrequency, 1));
        QVERIFY(spin);
        QCOMPARE(spin->text(), QStringLiteral("6000"));
        QCOMPARE(spin->decimals(), 0);
        QVERIFY(spin->suffix().isEmpty());
        QVERIFY(qobject_cast<ScaledSpinBox *>(openEditor(kSource))); // no plaintexts either
    }

    void readOnlyAndLockedCellsGetNoEditor()
    {
        for (int i = 0; i < 4; ++i)
            QTest::ignoreMessage(QtWarningMsg, "edit: editing failed");
        QVERIFY(!openEditor(kFrequency));
        QVERIFY(!openEditor(kState));
        QVERIFY(openEditor(kService));
        QTest::keyClick(m_view->indexWidget(viewIndex(kService)), Qt::Key_Escape);
        m_model->state()->setPasswordLevel(PasswordLevel::CpReadWrite);
        QVERIFY(!openEditor(kService));
        const QModelIndex name
            = m_filter->mapFromSource(m_model->indexOf(kMaxFrequency, ParameterModel::NameColumn));
        m_view->edit(name);
        QVERIFY(!m_view->indexWidget(name));
    }
};

QTEST_MAIN(TestParameterDelegate)
#include "tst_parameterdelegate.moc"
