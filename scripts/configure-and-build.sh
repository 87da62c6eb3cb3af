#!/usr/bin/env bash
# Configure and build softgrasp in build/ (Release, 2 jobs, ccache if present).
# Usage: scripts/configure-and-build.sh [cmake --build extra arguments...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build" -j2 "$@"
