#pragma once

#include "link/ConnectionSettings.h"
#include "parameters/DriveDescription.h"

#include <QString>

namespace DriveDesk {

class ParameterModel;

// The favourites of the drive the window shows, kept in QSettings ("favourites/" and a key per
// drive). Favourites belong to a drive: its identification and serial number (In.10) where it
// has them, otherwise where it was reached. A parameter file of the drive shares its
// favourites; one without an identification has none remembered.
class DriveFavourites
{
public:
    explicit DriveFavourites(ParameterModel *model = nullptr)
        : m_model(model)
    { }

    // The model holds `drive` now (reached through `settings`; nullptr for a file): its
    // favourites as last saved go into the model.
    void restore(const DriveDescription &drive, const ConnectionSettings *settings);
    // The model's favourites, for the drive restored last; nothing while there is none.
    void save() const;
    // The model shows another drive, or none: nothing is saved until the next restore().
    void forget() { m_key.clear(); }

private:
    ParameterModel *m_model = nullptr;
    QString m_key; // the drive's key under "favourites/"
};

} // namespace DriveDesk
