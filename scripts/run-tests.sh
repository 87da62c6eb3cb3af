#!/usr/bin/env bash
# The test suite: install dependencies, build, and run every test with CTest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-dependencies.sh"
# The library, programs and every test executable in one parallel pass, so
# that no test's time is a compile.
"$root/scripts/configure-and-build.sh" --target all tests
# Open MPI refuses to start as root unless told; harmless otherwise.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --test-dir "$root/build" -j2 --output-on-failure
