#!/usr/bin/env bash
# Runs tests again and again beside a load that keeps one processor core busy, as an engineer's
# laptop is with a virus scan or a compiler running: a busy machine may make DriveDesk slower,
# never wrong. A test that fails once fails the run (ctest --repeat until-fail).
#
#   tools/stress.sh [--repeat N] [--build DIR] [--quiet-machine] [WHICH ...]
#
# WHICH: `window` (the window's tests, label gui), `waiting` (the tests that wait on a line,
# build/tests/waiting), `all` (both, and every other test), or a ctest -R regular expression
# such as tst_mainwindow_edit. Default: window and waiting, 20 repetitions, ./build.
# --quiet-machine runs without the load, for a figure to compare with.
set -euo pipefail
cd "$(dirname "$0")/.."

repeat=20
build=build
load=1
which=()
while (($#)); do
    case $1 in
        --repeat) repeat=$2; shift 2 ;;
        --build) build=$2; shift 2 ;;
        --quiet-machine) load=0; shift ;;
        -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        -*) echo "stress.sh: unknown option $1" >&2; exit 2 ;;
        *) which+=("$1"); shift ;;
    esac
done
((${#which[@]})) || which=(window waiting)
[[ $repeat =~ ^[1-9][0-9]*$ ]] || { echo "stress.sh: --repeat takes a count, not '$repeat'" >&2; exit 2; }
[ -f "$build/CTestTestfile.cmake" ] \
    || { echo "stress.sh: $build is no build directory: run tools/setup.sh first" >&2; exit 2; }

export QT_QPA_PLATFORM=offscreen
busy=""
stop_load() { [ -n "$busy" ] && kill "$busy" 2>/dev/null; wait 2>/dev/null || true; }
trap stop_load EXIT
if ((load)); then
    # One core kept busy at normal priority for as long as the tests run.
    bash -c 'while :; do :; done' &
    busy=$!
fi

log=$(mktemp -d "${TMPDIR:-/tmp}/drivedesk-stress.XXXXXX")
status=0
run() { # name, ctest arguments...
    local name=$1 started result=0
    shift
    started=$(date +%s)
    ctest --output-on-failure --timeout 900 --repeat until-fail:"$repeat" "$@" \
        >"$log/$name.log" 2>&1 || result=$?
    local summary
    summary=$(grep -E '^[0-9]+% tests passed|tests failed out of' "$log/$name.log" | tail -1)
    printf '%-28s %s (%d s, %d repetitions%s)\n' "$name" "${summary:-no summary}" \
        $(($(date +%s) - started)) "$repeat" "$( ((load)) && echo ', one core busy')"
    if ((result)); then
        status=1
        echo "--- $name failed; its log: $log/$name.log"
        grep -E 'FAIL|Failed|\*\*\*' "$log/$name.log" | head -20 || true
    fi
}

for item in "${which[@]}"; do
    case $item in
        window) run window --test-dir "$build" -L gui -j2 ;;
        waiting) run waiting --test-dir "$build/tests/waiting" -j16 ;;
        all)
            run others --test-dir "$build" --label-exclude waiting -j2
            run waiting --test-dir "$build/tests/waiting" -j16 ;;
        *) run "$item" --test-dir "$build" -R "$item" -j2 ;;
    esac
done
echo "logs: $log"
exit "$status"
