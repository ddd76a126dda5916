#pragma once

#include <QList>

namespace DriveDesk {

class WindowFeature;
class WindowFrame;

// The window's features, made for `frame` in the order their actions appear. A new feature is
// one line here.
QList<WindowFeature *> makeWindowFeatures(WindowFrame &frame);

} // namespace DriveDesk
