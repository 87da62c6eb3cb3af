#!/usr/bin/env bash
# Benchmark of the arm_grasp study (explicit, the shipped arm_grasp.prm):
# the default mesh (4,608 cells, 17k displacement DoFs) and a fine one
# (2, 3, 1, 8 radial cells in skin, fat, fascia, muscle; 128 around; 24
# cells along the grasp zone: 71,680 cells, 236k DoFs; mass scaling to a
# 40 us target instead of 20 us, see doc/benchmarks.md). The default case
# runs MuJoCo and writes the kinematics file; the fine case reads it.
# Usage (from the repository root, after building):
#   benchmarks/arm_grasp.sh [build-dir] [ranks] [cases]
# with cases "default fine" (the default) or one of them. Results go to
# doc/benchmarks.md by hand, with date, machine and command.
set -euo pipefail
build=${1:-build}
ranks=${2:-2}
cases=${3:-default fine}
dir="$build/studies/arm_grasp"
for name in $cases; do
  out="benchmark_$name"
  edits=(-e "s/set Directory    = arm_grasp_output/set Directory    = $out/")
  if [ "$name" = fine ]; then
    if [ ! -f "$dir/benchmark_default/kinematics.h5" ]; then
      echo "the fine case reads benchmark_default/kinematics.h5: run the default case first"
      exit 1
    fi
    mkdir -p "$dir/$out"
    cp "$dir/benchmark_default/kinematics.h5" "$dir/$out/"
    edits+=(-e "s/set Rigid stage         = run/set Rigid stage         = read/"
            -e "s/set Radial cells          = 1, 1, 1, 3/set Radial cells          = 2, 3, 1, 8/"
            -e "s/set Circumferential cells = 48/set Circumferential cells = 128/"
            -e "s/set Grasp zone cells      = 8/set Grasp zone cells      = 24/"
            -e "s/set Mass scaling time step = 2e-5/set Mass scaling time step = 4e-5/")
  fi
  sed "${edits[@]}" "$dir/arm_grasp.prm" > "$dir/$out.prm"
  echo "== $name, $ranks rank(s)"
  (cd "$dir" && /usr/bin/time -f "total %e s wall, peak %M kB (largest rank)" \
    mpirun --allow-run-as-root -np "$ranks" ./arm_grasp "$out.prm" 2>&1 |
    grep -E "Rigid stage|Mesh:|Explicit dynamics:|Total wallclock|^\| (contact|output|setup|time steps) |_link +normal|total .* wall|Injury|^  [a-z ]+ \(id|e_max|e_min|beyond|contact surface|above|balance on the body|penetration")
done
