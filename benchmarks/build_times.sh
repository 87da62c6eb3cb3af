#!/usr/bin/env bash
# Build and test times of the working loop (doc/benchmarks.md, "Build and
# test times"): a fresh configure and build of every target and every test
# executable, one edited library source, one edited contact header, a test
# re-run after the library changed, and `ctest -L quick`. Compilations are
# real (ccache off), so the figures are those of a fresh clone or a real
# edit. Prints one CSV line per figure: what,seconds,peak_resident_MiB.
#
# Usage, from the repository root (takes about 20 minutes on 2 cores):
#   benchmarks/build_times.sh [build directory] [extra cmake arguments...]
# e.g. benchmarks/build_times.sh /tmp/bt
#      benchmarks/build_times.sh /tmp/bt-old -G "Unix Makefiles" \
#        -DSOFTGRASP_PRECOMPILED_HEADERS=OFF -DSOFTGRASP_LINKER=gold
# The build directory is deleted first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-/tmp/softgrasp-build-times}
shift || true
cmake_args=("$@")
if [ ${#cmake_args[@]} -eq 0 ]; then cmake_args=(-G Ninja); fi
export CCACHE_DISABLE=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# measure NAME COMMAND...: wall time and the peak resident memory of the
# largest process (GNU time's %M, kB) of COMMAND.
measure() {
  local name=$1
  shift
  local log
  log=$(mktemp)
  /usr/bin/time -f "%e %M" -o "$log" "$@" >"$log.out" 2>&1 || {
    echo "build_times.sh: '$*' failed; its output:" >&2
    tail -40 "$log.out" >&2
    exit 1
  }
  read -r seconds kb <"$log"
  echo "$name,$seconds,$((kb / 1024))"
  rm -f "$log" "$log.out"
}

rm -rf "$build"
echo "what,seconds,peak_resident_MiB"
measure configure cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  "${cmake_args[@]}"
measure library cmake --build "$build" -j2 --target softgrasp
measure all_targets cmake --build "$build" -j2
measure test_executables cmake --build "$build" -j2 --target tests

# one edited library source: the library rebuilt (and nothing relinked)
touch "$root/lib/source/contact/mortar_contact.cc"
measure edit_source_library cmake --build "$build" -j2 --target softgrasp
measure edit_source_all cmake --build "$build" -j2 --target all tests
# one test after that: it reruns (its library changed) without a relink
measure rerun_test_after_edit ctest --test-dir "$build" -R '^contact/nodal_law'
touch "$root/lib/source/contact/mortar_contact.cc"
cmake --build "$build" -j2 --target softgrasp >/dev/null
measure rerun_test_after_edit_warm ctest --test-dir "$build" -R '^contact/nodal_law'

# one edited header of contact/: every target that includes it
touch "$root/lib/include/softgrasp/contact/mortar_contact.h"
measure edit_contact_header cmake --build "$build" -j2 --target all tests

measure ctest_quick ctest --test-dir "$build" -j2 -L quick
