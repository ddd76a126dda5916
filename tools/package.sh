#!/usr/bin/env bash
# Makes the Debian package build/package/drivedesk_<version>_<arch>.deb with CPack from the build
# in ./build (the one the tests ran in): the three programs are brought up to date, nothing else
# is built. With --check it then checks the package: the files it must hold, its dependencies,
# lintian, the AppStream metadata and the desktop entry, and that the programs unpacked from it
# answer --version.
set -euo pipefail
cd "$(dirname "$0")/.."

check=false
case ${1-} in
    --check) check=true ;;
    "") ;;
    *)
        echo "usage: tools/package.sh [--check]" >&2
        exit 2
        ;;
esac

build=build
out=$build/package
# One build at a time in ./build: anything else building there takes the same lock.
lock=${DRIVEDESK_BUILD_LOCK:-/tmp/drivedesk-build.lock}
[ -f "$build/CMakeCache.txt" ] || { echo "no build in ./$build: run tools/setup.sh" >&2; exit 2; }

mkdir -p "$out"
flock "$lock" cmake --build "$build" --target drivedesk drivedesk-cli drivedesk-sim \
    >"$out/build.log" 2>&1 || { cat "$out/build.log" >&2; exit 1; }
started=$SECONDS
# Only this version's package in the folder: `apt-get install ./build/package/drivedesk_*.deb`.
rm -f "$out"/drivedesk_*.deb
# The packaging settings (packaging/Packaging.cmake) skip CPack's usual build of everything.
flock "$lock" cpack --config "$build/CPackConfig.cmake" -B "$out" >"$out/cpack.log" 2>&1 \
    || { cat "$out/cpack.log" >&2; exit 1; }
version=$(sed -n 's/^set(CPACK_PACKAGE_VERSION "\(.*\)")$/\1/p' "$build/CPackConfig.cmake")
deb=$out/drivedesk_${version}_$(dpkg --print-architecture).deb
[ -f "$deb" ] || { cat "$out/cpack.log" >&2; echo "CPack made no $deb" >&2; exit 1; }
echo "package: $deb ($((SECONDS - started)) s)"
$check || exit 0

failures=0
fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

# What a system install needs, each in the place Debian and the desktops look for it.
app_id=io.github.drivedesk.DriveDesk
contents=$(dpkg-deb --contents "$deb" | awk '{print $NF}')
required=(
    ./usr/bin/drivedesk ./usr/bin/drivedesk-cli ./usr/bin/drivedesk-sim
    ./usr/share/applications/$app_id.desktop
    ./usr/share/metainfo/$app_id.metainfo.xml
    ./usr/share/icons/hicolor/scalable/apps/drivedesk.svg
    ./usr/share/man/man1/drivedesk.1.gz ./usr/share/man/man1/drivedesk-cli.1.gz
    ./usr/share/man/man1/drivedesk-sim.1.gz
    ./usr/share/bash-completion/completions/drivedesk
    ./usr/share/bash-completion/completions/drivedesk-cli
    ./usr/share/bash-completion/completions/drivedesk-sim
    ./usr/share/doc/drivedesk/copyright ./usr/share/doc/drivedesk/changelog.gz
    ./usr/share/doc/drivedesk/parameter-file.md
)
for size in 16 32 48 64 128 256; do
    required+=("./usr/share/icons/hicolor/${size}x$size/apps/drivedesk.png")
done
for file in "${required[@]}"; do
    grep -qxF "$file" <<<"$contents" || fail "the package lacks $file"
done

# Qt's libraries and FFTW's (the scope's spectrum) come from dpkg-shlibdeps; the platform plugin,
# git (a plant's backup history) and translations it cannot see.
depends=$(dpkg-deb --field "$deb" Depends)
recommends=$(dpkg-deb --field "$deb" Recommends)
echo "Depends: $depends"
echo "Recommends: $recommends"
for package in libqt6core6 libqt6widgets6 libqt6serialport6 libfftw3-double3 qt6-qpa-plugins git; do
    grep -qE "(^|, )$package( |,|$)" <<<"$depends" || fail "Depends lacks $package"
done
grep -qE "(^|, )qt6-translations-l10n( |,|$)" <<<"$recommends" \
    || fail "Recommends lacks qt6-translations-l10n"

# Errors fail the check; warnings are shown (an override needs its reason beside it).
lintian_status=0
lintian_report=$(lintian --fail-on error "$deb" 2>&1) || lintian_status=$?
lintian_report=$(grep -v 'running with root privileges' <<<"$lintian_report" || true)
echo "lintian: ${lintian_report:-no errors, no warnings}"
((lintian_status == 0)) || fail "lintian reports errors"

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
dpkg-deb -x "$deb" "$scratch"
appstreamcli validate --no-net "$scratch/usr/share/metainfo/$app_id.metainfo.xml" \
    || fail "the AppStream metadata does not validate"
desktop-file-validate "$scratch/usr/share/applications/$app_id.desktop" \
    || fail "the desktop entry does not validate"
grep -qF "<launchable type=\"desktop-id\">$app_id.desktop</launchable>" \
    "$scratch/usr/share/metainfo/$app_id.metainfo.xml" \
    || fail "the metadata's launchable is not $app_id.desktop"
grep -qF "<release version=\"$version\"" "$scratch/usr/share/metainfo/$app_id.metainfo.xml" \
    || fail "the metadata has no release $version"

for program in drivedesk drivedesk-cli drivedesk-sim; do
    file "$scratch/usr/bin/$program" | grep -q ', stripped' || fail "$program is not stripped"
    answer=$(QT_QPA_PLATFORM=offscreen "$scratch/usr/bin/$program" --version 2>&1) || true
    echo "$program --version: $answer"
    [ "$answer" = "$program $version" ] || fail "$program --version says \"$answer\""
done

if ((failures)); then
    echo "$deb: $failures check(s) failed" >&2
    exit 1
fi
echo "$deb: all checks passed (packaged and checked in $((SECONDS - started)) s)"
