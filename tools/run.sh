#!/usr/bin/env bash
# Installs what is missing, builds, and starts DriveDesk on the simulated drive. Arguments go
# to drivedesk, e.g. --protocol din66019ii --language de.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
exec build/app/gui/drivedesk --connect sim "$@"
