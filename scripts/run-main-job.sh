#!/usr/bin/env bash
# The main job: install dependencies, build, and run the tissue_curves
# example, which prints the stress-stretch response of every tissue preset
# and writes a CSV file and PNG plots to
#   build/examples/tissue_curves/tissue_curves_output/
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-dependencies.sh"
"$root/scripts/configure-and-build.sh" --target tissue_curves
cd "$root/build/examples/tissue_curves"
./tissue_curves tissue_curves.prm
echo "Results: $(pwd)/tissue_curves_output/ (uniaxial.png, equibiaxial.png, tissue_curves.csv)"
