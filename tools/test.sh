#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite twice: as built in ./build (and
# checks the Debian package made of it), and under AddressSanitizer and UndefinedBehaviorSanitizer
# (leaks too) in ./build-sanitize.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
export QT_QPA_PLATFORM=offscreen
ctest --test-dir build --output-on-failure -j2 --timeout 600
# The Debian package of that build, checked (tools/package.sh).
tools/package.sh --check

# The sanitizers' options come with the tests (tests/CMakeLists.txt).
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DDRIVEDESK_SANITIZE=ON \
    -DDRIVEDESK_BUILD_BENCHMARKS=OFF
cmake --build build-sanitize -j"$(nproc)"
ctest --test-dir build-sanitize --output-on-failure -j2 --timeout 600
