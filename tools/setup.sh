#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages DriveDesk needs that are missing, then configures and
# builds it in ./build. Used by tools/run.sh and tools/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
    cmake g++ make ninja-build pkg-config ccache
    qt6-base-dev qt6-serialport-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    qt6-qpa-plugins qt6-translations-l10n libqt6sql6-sqlite libqcustomplot-dev libfftw3-dev
    xvfb xauth socat git
    dpkg-dev lintian appstream desktop-file-utils file
)

missing=()
for package in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
        || missing+=("$package")
done
if ((${#missing[@]})); then
    echo "Installing: ${missing[*]}"
    sudo=""
    [ "$(id -u)" -ne 0 ] && sudo=sudo
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
        "${missing[@]}"
fi

# --packages: only the packages (tools/test.sh --sanitized builds a tree of its own).
[ "${1:-}" = "--packages" ] && exit 0

# The benchmarks are built in a Release tree of their own (docs/performance.md), not here.
# A unity build (cmake/BuildSpeed.cmake) compiles a fresh tree in about two thirds of the time.
cmake -S . -B build $(tools/generator.sh build) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DDRIVEDESK_BUILD_BENCHMARKS=OFF -DDRIVEDESK_UNITY_BUILD=ON
cmake --build build -j"$(nproc)"
