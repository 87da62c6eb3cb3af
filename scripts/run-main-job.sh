#!/usr/bin/env bash
# The main job: install dependencies, build, and run
#  1. the tissue_curves example: stress-stretch response of every tissue
#     preset, CSV file and PNG plots in
#       build/examples/tissue_curves/tissue_curves_output/
#  2. the cook_membrane example: the quasi-static finite-strain solver on
#     Cook's membrane, compared with the published tip deflection; VTU/PVD
#     and history CSV in build/examples/cook_membrane/cook_membrane_output/
#  3. the hertz_indentation example: a rigid sphere pressed into soft
#     tissue with mortar contact, compared with Hertz's force; contact
#     fields (VTU) and force history (CSV) in
#     build/examples/hertz_indentation/hertz_output/
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-dependencies.sh"
"$root/scripts/configure-and-build.sh" --target tissue_curves cook_membrane \
  hertz_indentation
cd "$root/build/examples/tissue_curves"
./tissue_curves tissue_curves.prm
echo "Results: $(pwd)/tissue_curves_output/ (uniaxial.png, equibiaxial.png, tissue_curves.csv)"
cd "$root/build/examples/cook_membrane"
./cook_membrane cook_membrane.prm
echo "Results: $(pwd)/cook_membrane_output/ (cook.pvd, cook_history.csv)"
cd "$root/build/examples/hertz_indentation"
./hertz_indentation hertz_indentation.prm
echo "Results: $(pwd)/hertz_output/ (hertz.pvd, hertz_contact.csv, hertz_history.csv)"
