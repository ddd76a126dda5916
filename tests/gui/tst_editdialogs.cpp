#include "edit/PasswordDialog.h"
#include "edit/SetsDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

using namespace DriveDesk;

namespace {

QPushButton *okButton(QDialog &dialog)
{
    return dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
}

QPushButton *button(QDialog &dialog, const QString &text)
{
    for (QPushButton *candidate : dialog.findChildren<QPushButton *>()) {
        if (candidate->text() == text)
            return candidate;
    }
    return nullptr;
}

bool showsText(QDialog &dialog, const QString &text)
{
    for (QLabel *label : dialog.findChildren<QLabel *>()) {
        if (label->text().contains(text))
            return true;
    }
    return false;
}

} // namespace

// The password dialog and the sets dialog as a user meets them.
class TestEditDialogs : public QObject
{
    Q_OBJECT
private slots:
    void passwordDialogShowsTheLevelAndTakesANumber()
    {
        PasswordDialog dialog;
        QVERIFY(showsText(dialog, QStringLiteral("not read yet")));
        dialog.setLevel(PasswordLevel::Application);
        QVERIFY(showsText(dialog, passwordLevelName(PasswordLevel::Application)));
        QVERIFY(!okButton(dialog)->isEnabled());
        QCOMPARE(dialog.password(), std::nullopt);

        auto *field = dialog.findChild<QLineEdit *>();
        QCOMPARE(field->echoMode(), QLineEdit::Password);
        QTest::keyClicks(field, QStringLiteral("5x0-0"));
        QCOMPARE(field->text(), QStringLiteral("500"));
        QVERIFY(okButton(dialog)->isEnabled());
        QCOMPARE(dialog.password(), 500);

        // OK asks the drive and waits: a refusal keeps the dialog open with the drive's reason
        // and the number selected for another try; only an accepted password closes it.
        dialog.show();
        QSignalSpy entered(&dialog, &PasswordDialog::passwordEntered);
        QTest::mouseClick(okButton(dialog), Qt::LeftButton);
        QCOMPARE(entered.size(), 1);
        QCOMPARE(entered.constFirst().at(0).toInt(), 500);
        QVERIFY(dialog.isVisible());
        QVERIFY(dialog.isChecking());
        QVERIFY(!okButton(dialog)->isEnabled());
        QTest::mouseClick(okButton(dialog), Qt::LeftButton);
        QCOMPARE(entered.size(), 1);

        dialog.passwordRefused(QStringLiteral("password invalid"));
        QVERIFY(dialog.isVisible());
        QVERIFY(showsText(dialog, QStringLiteral("Not accepted: password invalid")));
        QVERIFY(okButton(dialog)->isEnabled());
        QCOMPARE(field->selectedText(), QStringLiteral("500"));

        QTest::keyClicks(field, QStringLiteral("440"));
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(entered.size(), 2);
        QCOMPARE(entered.constLast().at(0).toInt(), 440);
        dialog.passwordAccepted();
        QVERIFY(!dialog.isVisible());
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
    }

    void setsDialogChoosesSets()
    {
        SetsDialog dialog(SetsDialog::Mode::ChooseSets);
        QCOMPARE(dialog.mode(), SetsDialog::Mode::ChooseSets);
        QCOMPARE(dialog.setMask(), quint8(0));
        QVERIFY(!okButton(dialog)->isEnabled());

        QTest::mouseClick(button(dialog, QStringLiteral("&All")), Qt::LeftButton);
        QCOMPARE(dialog.setMask(), quint8(0xFF));
        QVERIFY(okButton(dialog)->isEnabled());
        QTest::mouseClick(button(dialog, QStringLiteral("&None")), Qt::LeftButton);
        QCOMPARE(dialog.setMask(), quint8(0));
        QVERIFY(!okButton(dialog)->isEnabled());

        dialog.setActiveSet(2);
        const QList<QCheckBox *> boxes = dialog.findChildren<QCheckBox *>();
        QCOMPARE(boxes.size(), 8);
        QCheckBox *setTwo = nullptr;
        for (QCheckBox *box : boxes) {
            if (box->text() == QStringLiteral("Set 2 (active)"))
                setTwo = box;
        }
        QVERIFY(setTwo);
        setTwo->click();
        QCOMPARE(dialog.setMask(), quint8(0x04));
        dialog.setSetMask(0x81);
        QCOMPARE(dialog.setMask(), quint8(0x81));
        QVERIFY(okButton(dialog)->isEnabled());
    }

    void setsDialogChoosesACopy()
    {
        SetsDialog dialog(SetsDialog::Mode::CopySet);
        QCOMPARE(dialog.fromSet(), 0);
        QCOMPARE(dialog.toSet(), 1);
        QVERIFY(okButton(dialog)->isEnabled());
        QVERIFY(dialog.findChildren<QCheckBox *>().isEmpty());

        dialog.setCopy(3, 3);
        QVERIFY(!okButton(dialog)->isEnabled());
        const QList<QComboBox *> combos = dialog.findChildren<QComboBox *>();
        QCOMPARE(combos.size(), 2);
        combos.at(1)->setCurrentIndex(6);
        QCOMPARE(dialog.fromSet(), 3);
        QCOMPARE(dialog.toSet(), 6);
        QVERIFY(okButton(dialog)->isEnabled());
        dialog.setPrompt(QStringLiteral("Copy what?"));
        QVERIFY(showsText(dialog, QStringLiteral("Copy what?")));
    }
};

QTEST_MAIN(TestEditDialogs)
#include "tst_editdialogs.moc"
