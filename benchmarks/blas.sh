#!/usr/bin/env bash
# Benchmark of the BLAS/LAPACK that MUMPS (the direct solver) runs on: the
# same runs with Debian's reference BLAS and with the optimised one that
# scripts/install-dependencies.sh installs (OpenBLAS, serial), one after the
# other in the same session, so that the ratio holds on a noisy machine.
# Both libraries are Debian alternatives of libblas.so.3/liblapack.so.3; the
# reference one is picked per run by LD_LIBRARY_PATH.
# Usage (from the repository root, after building):
#   benchmarks/blas.sh [build-dir]
# Results go to doc/benchmarks.md by hand, with date, machine and command.
set -euo pipefail
build=${1:-build}
build=$(cd "$build" && pwd)
lib=/usr/lib/x86_64-linux-gnu
reference="$lib/blas:$lib/lapack"
if [ ! -e "$lib/openblas-serial/libblas.so.3" ]; then
  echo "OpenBLAS is not installed: run scripts/install-dependencies.sh" >&2
  exit 1
fi
echo "libblas.so.3 -> $(readlink -f "$lib/libblas.so.3")"
run() { # label, directory, command...
  local label=$1 dir=$2
  shift 2
  for blas in reference optimised; do
    local path=""
    [ "$blas" = reference ] && path=$reference
    echo "== $label, $blas BLAS"
    (cd "$dir" && LD_LIBRARY_PATH=$path /usr/bin/time \
      -f "total %e s wall, peak %M kB" "$@" 2>&1 |
      grep -E "force error|linear solve|total .* wall|Indentation:|link  *normal")
  done
}
run "Hertz, 14,739 Q2 DoFs, direct" "$build/benchmarks" \
  ./hertz_contact 8 1.5 0.05 2 4 direct 0
dir="$build/studies/sphere_squeeze"
sed -e "s/set Pictures            = true/set Pictures            = false/" \
    -e "s/set Directory    = sphere_squeeze_output/set Directory    = benchmark_blas/" \
    "$dir/sphere_squeeze.prm" > "$dir/benchmark_blas.prm"
run "sphere_squeeze default, direct" "$dir" ./sphere_squeeze benchmark_blas.prm
