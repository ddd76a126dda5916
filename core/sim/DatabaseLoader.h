#pragma once

#include "ParameterDatabase.h"

#include <QString>

#include <memory>

namespace DriveDesk::Sim {

// Builds the simulated F5 from its data files: keb_f5_params.csv (facts about real drives),
// completed by sim_f5_groups.csv, sim_f5_parameters.csv and sim_f5_plaintexts.csv.
// `directory` holds the four files (the compiled-in resources by default).
std::shared_ptr<ParameterDatabase> loadDatabase(const QString &directory);

// The standard simulated drive from the resources of drivedesk_sim, loaded once and shared.
// Thread-safe.
std::shared_ptr<const ParameterDatabase> standardDatabase();

// Where the compiled-in data files are.
QString resourceDirectory();

} // namespace DriveDesk::Sim
