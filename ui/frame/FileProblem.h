#pragma once

class QString;
class QWidget;

namespace DriveDesk {

// A file that could not be read or written, in a warning box titled by what the user did, as
// File > Open shows one: a status bar message alone goes unseen. Opened without blocking
// (open()), deleted when closed.
void showFileProblem(QWidget *parent, const QString &title, const QString &text);

} // namespace DriveDesk
