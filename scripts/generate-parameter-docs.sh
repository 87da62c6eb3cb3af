#!/usr/bin/env bash
# Regenerate doc/parameters/*.prm (every parameter with its documentation,
# printed by the programs themselves) from a built tree.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$root/doc/parameters"
"$root/build/examples/tissue_curves/tissue_curves" --print-parameters \
  > "$root/doc/parameters/tissue_curves.prm"
echo "wrote doc/parameters/tissue_curves.prm"
"$root/build/examples/material_fit/material_fit" --print-parameters \
  > "$root/doc/parameters/material_fit.prm"
echo "wrote doc/parameters/material_fit.prm"
"$root/build/examples/cook_membrane/cook_membrane" --print-parameters \
  > "$root/doc/parameters/solver.prm"
echo "wrote doc/parameters/solver.prm (every solver program: quasi-static and explicit)"
"$root/build/examples/hertz_indentation/hertz_indentation" --print-parameters \
  "$root/examples/hertz_indentation/hertz_indentation.prm" \
  > "$root/doc/parameters/contact_hertz_indentation.prm"
echo "wrote doc/parameters/contact_hertz_indentation.prm (all entries of a run with rigid bodies and contact)"
"$root/build/programs/softgrasp/softgrasp" --print-parameters \
  "$root/programs/softgrasp/tube_drag.prm" \
  > "$root/doc/parameters/softgrasp_tube_drag.prm"
echo "wrote doc/parameters/softgrasp_tube_drag.prm (the softgrasp program on a tube mesh with phases)"
if [ -x "$root/build/studies/sphere_squeeze/sphere_squeeze" ]; then
  (cd "$root/build/studies/sphere_squeeze" &&
    ./sphere_squeeze --print-parameters sphere_squeeze.prm) \
    > "$root/doc/parameters/sphere_squeeze.prm"
  echo "wrote doc/parameters/sphere_squeeze.prm (the sphere_squeeze study: rigid environment, indentation study and solver)"
fi
if [ -x "$root/build/studies/arm_grasp/arm_grasp" ]; then
  (cd "$root/build/studies/arm_grasp" &&
    ./arm_grasp --print-parameters arm_grasp.prm) \
    > "$root/doc/parameters/arm_grasp.prm"
  echo "wrote doc/parameters/arm_grasp.prm (the arm_grasp study: arm scene, layered limb, tissue materials)"
fi
if [ -x "$root/build/studies/grasp_pull_sweep/grasp_pull_sweep" ]; then
  (cd "$root/build/studies/grasp_pull_sweep" &&
    ./grasp_pull_sweep --print-parameters grasp_pull_sweep.prm) \
    > "$root/doc/parameters/grasp_pull_sweep.prm"
  echo "wrote doc/parameters/grasp_pull_sweep.prm (the grasp_pull_sweep study: grip levels, pulls)"
fi
