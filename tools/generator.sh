#!/usr/bin/env bash
# Prints the CMake generator option for the build directory $1: Ninja where it is installed and
# the directory is new. Ninja starts the next compile sooner than make's nested makefiles and
# finds a built tree up to date in a second instead of fifteen; a directory configured before
# keeps the generator it has (CMake refuses to change it).
if [ ! -f "$1/CMakeCache.txt" ] && command -v ninja >/dev/null; then
    echo "-G Ninja"
fi
