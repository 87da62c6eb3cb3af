#!/usr/bin/env bash
# Benchmark of the grasp_pull_sweep study on the shipped
# grasp_pull_sweep.prm (default arm: 4,608 cells, 17k displacement DoFs,
# 13 levels, 2 cm pulls): the whole sweep with one integrator, timed per
# stage (MuJoCo, the finite element closing, every level's pull).
# Usage (from the repository root, after building):
#   benchmarks/grasp_pull_sweep.sh [build-dir] [integrator] [ranks] [levels]
# integrator: "quasi-static" (the default) or "explicit dynamic"; levels:
# 13 by default. Each run starts afresh in benchmark_<integrator>/.
# Results go to doc/benchmarks.md by hand, with date, machine and command.
set -euo pipefail
build=${1:-build}
integrator=${2:-quasi-static}
ranks=${3:-1}
levels=${4:-13}
dir="$build/studies/grasp_pull_sweep"
out="benchmark_${integrator// /_}"
rm -rf "${dir:?}/$out"
sed -e "s/set Directory    = grasp_pull_sweep_output/set Directory    = $out/" \
    -e "s/set Integrator        = .*/set Integrator        = $integrator/" \
    -e "s/set Levels             = 13/set Levels             = $levels/" \
    "$dir/grasp_pull_sweep.prm" > "$dir/$out.prm"
echo "== $integrator, $levels levels, $ranks rank(s)"
(cd "$dir" && /usr/bin/time -f "total %e s wall, peak %M kB (largest rank)" \
  mpirun --allow-run-as-root -np "$ranks" ./grasp_pull_sweep "$out.prm" 2>&1 |
  grep -E "Rigid stage|^Mesh:|^Level|Finite element (closing|stage)|total .* wall")
