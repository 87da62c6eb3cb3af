#!/usr/bin/env bash
# The main job: install dependencies, build, and run the sphere_squeeze
# study from MuJoCo kinematics alone:
#  1. MuJoCo closes the three-finger hand on a free sphere (radius 40 mm) to
#     the equilibrium grasp and records the fingers closing 0.04 rad further
#     (kinematics.h5);
#  2. the finite element solver drives the same capsule links into a rubber
#     sphere on those poses, with mortar contact and Coulomb friction.
# Results in build/studies/sphere_squeeze/sphere_squeeze_output/:
#   sphere_picture.png  the indented sphere coloured by e_max, with the links
#   sphere_forces.png   normal and lateral force against closure per link,
#                       finite elements next to MuJoCo
#   sphere_links.csv    the same numbers; sphere.pvd (e_max, contact fields)
#   kinematics.h5       the MuJoCo kinematics (doc/kinematics_file.md)
# The tutorial examples (tissue_curves, cook_membrane, hertz_indentation,
# ironing) are built too and run by the test suite.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-dependencies.sh"
"$root/scripts/configure-and-build.sh" --target sphere_squeeze
cd "$root/build/studies/sphere_squeeze"
./sphere_squeeze sphere_squeeze.prm
echo "Results: $(pwd)/sphere_squeeze_output/ (sphere_picture.png, sphere_forces.png, sphere_links.csv, sphere.pvd, kinematics.h5)"
