#!/usr/bin/env bash
# Configure and build softgrasp in build/ (Release, Ninja, 2 jobs, ccache
# and the precompiled header; cmake/build_speed.cmake).
# Usage: scripts/configure-and-build.sh [cmake --build extra arguments...]
#   e.g. scripts/configure-and-build.sh --target softgrasp
#        scripts/configure-and-build.sh --target all tests   (what CI builds)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
generator=()
# A build/ configured before with another generator keeps it (CMake refuses
# to switch); a new one uses Ninja when it is installed.
if [ ! -f "$root/build/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1; then
  generator=(-G Ninja)
fi
cmake -S "$root" -B "$root/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build" -j2 "$@"
