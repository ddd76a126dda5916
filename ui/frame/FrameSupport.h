#pragma once

#include <QApplication>
#include <QDir>
#include <QIcon>
#include <QStyle>

namespace DriveDesk {

// The desktop theme's icon, or the style's where the theme has none: for the window's
// actions, its features' and the telegram monitor's.
inline QIcon themedIcon(const char *theme, QStyle::StandardPixmap fallback)
{
    return QIcon::fromTheme(QString::fromLatin1(theme),
                            QApplication::style()->standardIcon(fallback));
}

// A path as the window and its features name it in messages and titles.
inline QString shownPath(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

// Dialogs open with open() and act in a handler: no nested event loop, and what the handler
// needs it reads when the dialog closes, not before it opened.
template<typename Dialog>
Dialog *openDialog(Dialog *dialog)
{
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

} // namespace DriveDesk
