#include "tst_mainwindow_support.h"

#include "Translations.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QGroupBox>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMainWindow>
#include <QPointer>
#include <QTabBar>

#include <algorithm>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

namespace {

// The key Alt opens a text with ("&Drive": D), empty for none; "&&" is an ampersand.
QString mnemonic(const QString &text)
{
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text.at(i) != QLatin1Char('&'))
            continue;
        if (text.at(i + 1) == QLatin1Char('&')) {
            ++i;
            continue;
        }
        return text.at(i + 1).toUpper();
    }
    return {};
}

// "menu File: Alt+O: '&Open...', '&Offline'" for every key two texts of one place share.
QStringList clashes(const QString &place, const QStringList &texts)
{
    QMap<QString, QStringList> byKey;
    for (const QString &text : texts) {
        const QString key = mnemonic(text);
        if (!key.isEmpty())
            byKey[key] << text;
    }
    QStringList found;
    for (auto it = byKey.cbegin(); it != byKey.cend(); ++it) {
        if (it.value().size() > 1) {
            found << QStringLiteral("%1: Alt+%2: '%3'")
                         .arg(place, it.key(), it.value().join(QStringLiteral("', '")));
        }
    }
    return found;
}

QString plain(QString text)
{
    return text.remove(QLatin1Char('&'));
}

// The items of one menu (a submenu is a place of its own).
QStringList menuClashes(const QMenu *menu)
{
    QStringList texts;
    for (QAction *action : menu->actions()) {
        if (!action->isSeparator() && action->isVisible())
            texts << action->text();
    }
    return clashes(QStringLiteral("menu %1").arg(plain(menu->title())), texts);
}

// The texts whose mnemonic works in `window` now: buttons, labels with a buddy, group boxes and
// tabs that are shown in it (a hidden widget's shortcut does nothing; a dialog is a window of
// its own).
QStringList widgetTexts(QWidget *window)
{
    QStringList texts;
    const QList<QWidget *> widgets = window->findChildren<QWidget *>();
    for (QWidget *widget : widgets) {
        if (widget->window() != window || !widget->isVisibleTo(window))
            continue;
        if (auto *button = qobject_cast<QAbstractButton *>(widget)) {
            texts << button->text();
        } else if (auto *label = qobject_cast<QLabel *>(widget)) {
            if (label->buddy())
                texts << label->text();
        } else if (auto *group = qobject_cast<QGroupBox *>(widget)) {
            texts << group->title();
        } else if (auto *tabs = qobject_cast<QTabBar *>(widget)) {
            for (int tab = 0; tab < tabs->count(); ++tab)
                texts << tabs->tabText(tab);
        }
    }
    return texts;
}

QStringList windowClashes(QWidget *window, const QString &place)
{
    QStringList texts = widgetTexts(window);
    if (auto *main = qobject_cast<QMainWindow *>(window)) {
        for (QAction *action : main->menuBar()->actions())
            texts << action->text();
    }
    QStringList found = clashes(place, texts);
    // The menu bar's menus, their submenus, and those of tool buttons.
    const QList<QMenu *> menus = window->findChildren<QMenu *>();
    for (const QMenu *menu : menus)
        found << menuClashes(menu);
    return found;
}

QList<QWidget *> shownWindows()
{
    QList<QWidget *> windows;
    const QList<QWidget *> widgets = QApplication::topLevelWidgets();
    for (QWidget *widget : widgets) {
        if (widget->isVisible() && !qobject_cast<QMenu *>(widget)
            && !widget->inherits("QTipLabel"))
            windows << widget;
    }
    return windows;
}

// Every dialog the window's menus open: the items whose text ends in "..." are triggered one
// by one and each window that comes up is looked at and closed. File choosers are Qt's own.
QStringList dialogClashes(MainWindow &window)
{
    QStringList found;
    QList<QAction *> items;
    for (QAction *top : window.menuBar()->actions()) {
        if (!top->menu())
            continue;
        const QList<QAction *> actions = top->menu()->actions();
        for (QAction *action : actions) {
            const QString text = plain(action->text());
            if (action->isEnabled() && action->isVisible() && !action->menu()
                && (text.endsWith(QStringLiteral("...")) || text.endsWith(QChar(0x2026))))
                items << action;
        }
    }
    for (QAction *action : std::as_const(items)) {
        const QList<QWidget *> before = shownWindows();
        action->trigger();
        QTest::qWait(200); // dialogs that read something first come up a moment later
        for (QWidget *shown : shownWindows()) {
            if (before.contains(shown))
                continue;
            const QPointer<QWidget> guard(shown);
            if (!qobject_cast<QFileDialog *>(shown)) {
                found << windowClashes(shown, QStringLiteral("%1 (%2)")
                                                  .arg(shown->windowTitle(), plain(action->text())));
            }
            if (auto *dialog = qobject_cast<QDialog *>(shown))
                dialog->reject();
            if (guard)
                guard->close();
        }
    }
    return found;
}

} // namespace

// Alt+letter reaches one thing in each place: the menu bar, every menu, the window with its
// filter bar and docks, and every dialog the menus open, in English and in German.
class TestMnemonics : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;

    QStringList allClashes(Language language)
    {
        m_settings.clear();
        MainWindow window(language);
        window.resize(1400, 900);
        window.show();
        if (!QTest::qWaitForWindowExposed(&window) || !connectAndRead(window, simulated()))
            return { QStringLiteral("the window did not read the simulated drive") };
        const QList<QDockWidget *> docks = window.findChildren<QDockWidget *>();
        for (QDockWidget *dock : docks)
            dock->show();
        QStringList found = windowClashes(&window, QStringLiteral("main window"));
        found << dialogClashes(window);
        found.removeDuplicates();
        return found;
    }

    // A clash not in `known` fails; the known ones, in texts this test's fixes do not reach,
    // are expected failures until they are fixed (then this fails as an unexpected pass, and
    // the entry goes).
    void verify(const QStringList &found, const QStringList &known)
    {
        QStringList unexpected;
        QStringList stillThere;
        for (const QString &clash : found) {
            const bool isKnown = std::any_of(known.cbegin(), known.cend(), [&](const QString &k) {
                return clash.contains(k);
            });
            (isKnown ? stillThere : unexpected) << clash;
        }
        QVERIFY2(unexpected.isEmpty(), qPrintable(unexpected.join(QLatin1Char('\n'))));
        if (!known.isEmpty())
            QEXPECT_FAIL("", "known clashes, listed in the test", Continue);
        QVERIFY2(stillThere.isEmpty(), qPrintable(stillThere.join(QLatin1Char('\n'))));
    }

private slots:
    void eachMnemonicIsUsedOnceInEnglish()
    {
        verify(allClashes(Language::English), {});
    }

    // Last: the German catalogue stays installed for the rest of the program.
    void eachMnemonicIsUsedOnceInGerman()
    {
        QVERIFY(installTranslations(QStringLiteral("de")));
        verify(allClashes(Language::German), {});
    }
};

QTEST_MAIN(TestMnemonics)
#include "tst_mnemonics.moc"
