#!/usr/bin/env bash
# Installs what is missing, builds, runs the whole test suite as built in ./build, and checks
# the Debian package made of it.
#   tools/test.sh --sanitized   the suite under AddressSanitizer and UndefinedBehaviorSanitizer
#                               (leaks too) in ./build-sanitize instead; CI runs both (.ci/run)
set -euo pipefail
cd "$(dirname "$0")/.."
sanitized=false
[ "${1:-}" = "--sanitized" ] && sanitized=true
if $sanitized; then bash tools/setup.sh --packages; else bash tools/setup.sh; fi
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

if ! $sanitized; then
    suite build
    # The Debian package of that build, checked (tools/package.sh).
    tools/package.sh --check
    exit 0
fi

# The sanitizers' options come with the tests (tests/CMakeLists.txt).
cmake -S . -B build-sanitize $(tools/generator.sh build-sanitize) -DCMAKE_BUILD_TYPE=Debug \
    -DDRIVEDESK_SANITIZE=ON -DDRIVEDESK_BUILD_BENCHMARKS=OFF -DDRIVEDESK_UNITY_BUILD=ON
cmake --build build-sanitize -j"$(nproc)"
suite build-sanitize
