#!/usr/bin/env bash
# Benchmark of the sphere_squeeze study: wall time of the rigid grasp
# (MuJoCo) and of the finite element indentation at a coarse resolution
# (2 global refinements of the 6-cell shell, Q1), the default (3, Q1) and a
# fine one (2 refinements with Q2 elements), mixed u-p-J, direct solver,
# pictures off; the final link forces show the mesh convergence. The
# contact is node-wise unless the third argument says 'faces' (the
# implicit default since 2026-12-07; the table in doc/benchmarks.md is
# node-wise, and on the Q2 mesh the faces leave MuJoCo's initial overlap
# unsettled, doc/contact.md). Usage (from the repository root, after
# building):
#   benchmarks/sphere_squeeze.sh [build-dir] [ranks] [nodes|faces]
# Results go to doc/benchmarks.md by hand, with date, machine and command.
set -euo pipefail
build=${1:-build}
ranks=${2:-1}
integration=${3:-nodes}
dir="$build/studies/sphere_squeeze"
for case in "2 1" "3 1" "2 2"; do
  set -- $case
  name="r$1_q$2"
  sed -e "s/set Global refinements = 3/set Global refinements = $1/" \
      -e "s/set Polynomial degree = 1/set Polynomial degree = $2/" \
      -e "s/set Pictures            = true/set Pictures            = false/" \
      -e "s/^  set Friction coefficient = 1.0$/&\n  set Potential integration = $integration/" \
      -e "s/set Directory    = sphere_squeeze_output/set Directory    = benchmark_$name/" \
      "$dir/sphere_squeeze.prm" > "$dir/benchmark_$name.prm"
  echo "== $1 refinements, Q$2, $ranks rank(s)"
  (cd "$dir" && /usr/bin/time -f "total %e s wall, peak %M kB" \
    mpirun --allow-run-as-root -np "$ranks" ./sphere_squeeze "benchmark_$name.prm" 2>&1 |
    grep -E "Rigid stage|Mesh:|Total wallclock|Indentation:|link  *normal|total .* wall")
done
