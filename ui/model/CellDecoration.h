#pragma once

#include "ParameterRow.h"

#include <QColor>
#include <QIcon>

namespace DriveDesk {

// The colours and icons that mark edit states, favourites and locked parameters. Colours are
// blended from the application palette at the time they are asked for, so they keep their
// contrast in light and dark themes. Icons are made on first use (they need a GUI application).
class CellDecoration
{
public:
    QColor background(EditState state) const;
    QIcon icon(EditState state) const;
    // A star for a favourite, an empty icon of the same size otherwise so that ids line up.
    QIcon favouriteIcon(bool favourite) const;
    QColor lockedText() const;
    // The value cells of a read-only parameter: the greyed ground of a field that takes no input.
    QColor readOnlyBackground() const;

private:
    mutable QIcon m_star;
    mutable QIcon m_noStar;
};

} // namespace DriveDesk
