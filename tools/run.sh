#!/usr/bin/env bash
# Installs what is missing, builds, and starts DriveDesk on the simulated drive.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
exec build/app/cli/drivedesk-cli --connect sim scan --format table "$@"
