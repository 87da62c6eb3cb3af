#!/usr/bin/env bash
# Benchmark of the direct solver's reuse of MUMPS' symbolic factorisation
# ('Linear solver/Reuse symbolic factorization'): the same runs with the
# ordering and symbolic factorisation kept for the whole run (true, the
# default) and redone at every Newton step (false, as before), one after
# the other in the same session.
# Usage (from the repository root, after building):
#   benchmarks/direct_reuse.sh [build-dir]
# Results go to doc/benchmarks.md by hand, with date, machine and command.
set -euo pipefail
build=${1:-build}
build=$(cd "$build" && pwd)
run() { # label, directory, program, parameter file
  local label=$1 dir=$2 program=$3 prm=$4
  for reuse in false true; do
    local file="benchmark_reuse_$reuse.prm"
    sed -e "s/^subsection Linear solver$/subsection Linear solver\n  set Reuse symbolic factorization = $reuse/" \
        -e "s/set Pictures            = true/set Pictures            = false/" \
        -e "s/^\(  set Directory *= *\).*/\1benchmark_reuse_$reuse/" \
        "$dir/$prm" > "$dir/$file"
    grep -q "Reuse symbolic factorization = $reuse" "$dir/$file" ||
      { echo "no 'Linear solver' subsection in $prm" >&2; exit 1; }
    echo "== $label, reuse $reuse"
    (cd "$dir" && /usr/bin/time -f "total %e s wall, peak %M kB" \
      "./$program" "$file" 2>&1 |
      grep -E "^\| linear solve|^\| assembly|total .* wall|At the end|normal .* drag|thumb_proximal/")
  done
}
run "sphere_squeeze default" "$build/studies/sphere_squeeze" sphere_squeeze \
  sphere_squeeze.prm
run "frictional_drag example" "$build/examples/frictional_drag" \
  frictional_drag frictional_drag.prm
