#!/usr/bin/env bash
# Benchmark of the frictional drag (examples/frictional_drag, plane strain,
# mu = 0.5, 20 mm of pull at 20 mm/s): implicit dynamics (0.5 mm of pull per
# step) against the explicit solver with the shipped damping (mass 50 1/s,
# stiffness 0.3), on 120 x 20 and 240 x 40 cells, on 1 and 2 ranks. Prints
# the wall time, the steps and the mean normal force and drag over 8-20 mm
# of pull (N/m).
# Usage (from the repository root, after building):
#   benchmarks/frictional_drag.sh [build-dir] [meshes] [ranks]
# with meshes "120,20 240,40" and ranks "1 2" by default. Results go to
# doc/benchmarks.md by hand, with date, machine and command. Contact is
# node-wise ('Potential integration = nodes', penalty 100), as when its rows
# were measured: the example's own face contact runs the explicit
# integrator on one rank only.
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
meshes=${2:-120,20 240,40}
ranks_list=${3:-1 2}
prm=$(pwd)/examples/frictional_drag/frictional_drag.prm
exe=$build/examples/frictional_drag/frictional_drag
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for mesh in $meshes; do
  for integrator in "implicit dynamic" "explicit dynamic"; do
    for ranks in $ranks_list; do
      name="${mesh/,/x}_${integrator%% *}_$ranks"
      sed -e "s/set Subdivisions = 60, 10/set Subdivisions = ${mesh/,/, }/" \
          -e "s/set Integrator = implicit dynamic/set Integrator = $integrator/" \
          -e "s/set Directory = frictional_drag_output/set Directory = $name/" \
          -e "s/set VTU interval = 4/set VTU interval = 0/" \
          -e "s/set Potential integration = faces/set Potential integration = nodes/" \
          -e "s/set Penalty factor        = 1000/set Penalty factor        = 100/" \
          "$prm" > "$name.prm"
      start=$(date +%s.%N)
      mpirun --allow-run-as-root -np "$ranks" "$exe" "$name.prm" > "$name.log" 2>&1
      end=$(date +%s.%N)
      steps=$(grep -oE "^(Record|Step) +[0-9]+.*steps +[0-9]+" "$name.log" |
                tail -1 | grep -oE "steps +[0-9]+$" || true)
      [ -n "$steps" ] || steps="steps $(grep -cE '^Step +[0-9]+ +t = ' "$name.log")"
      means=$(awk '!/^#/ && NF >= 3 && $1 >= 0.9 - 1e-9 { n++; N += $2; D += $3 }
                   END { printf "normal %.2f N/m, drag %.2f N/m", N / n, D / n }' \
                "$name/drag_forces.dat")
      printf "%-9s %-17s %d rank(s): %7.1f s wall, %s, %s\n" "$mesh" \
        "$integrator" "$ranks" "$(echo "$end - $start" | bc)" "$steps" "$means"
    done
  done
done
