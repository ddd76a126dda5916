#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite twice: as built in ./build (and
# checks the Debian package made of it), and under AddressSanitizer and UndefinedBehaviorSanitizer
# (leaks too) in ./build-sanitize.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
export QT_QPA_PLATFORM=offscreen

# One build's suite. The tests that wait on a line (build/tests/waiting, tests/CMakeLists.txt)
# all run at once beside the others, which share the cores: they need almost no CPU, and one
# after another they would be most of the suite's time. Their report follows the others'.
suite() {
    local dir=$1 waiting status=0
    ctest --test-dir "$dir/tests/waiting" --output-on-failure -j16 --timeout 600 \
        >"$dir/waiting-tests.log" 2>&1 &
    waiting=$!
    ctest --test-dir "$dir" --label-exclude waiting --output-on-failure -j2 --timeout 600 \
        || status=$?
    wait "$waiting" || status=$?
    echo "The tests that wait on a line ($dir/tests/waiting):"
    cat "$dir/waiting-tests.log"
    return "$status"
}

suite build
# The Debian package of that build, checked (tools/package.sh).
tools/package.sh --check

# The sanitizers' options come with the tests (tests/CMakeLists.txt).
cmake -S . -B build-sanitize $(tools/generator.sh build-sanitize) -DCMAKE_BUILD_TYPE=Debug \
    -DDRIVEDESK_SANITIZE=ON \
    -DDRIVEDESK_BUILD_BENCHMARKS=OFF
cmake --build build-sanitize -j"$(nproc)"
suite build-sanitize
