#!/usr/bin/env bash
# The deep 3D drag in CalculiX, the independent reference of issue 63:
# the same capsule, block, neo-Hookean energy (quadratic volumetric term),
# friction and pull as examples/frictional_drag/deep_drag_3d.prm, written
# by calculix/deep_drag_3d_inp.py and solved by Debian's calculix-ccx
# (installed by scripts/install-dependencies.sh). Not part of CI.
# Per run it keeps <name>.inp, .dat, .sta, .log and <name>.csv (the forces
# on the finger every 0.25 mm of travel, calculix/dat_to_csv.py) in the
# output directory and prints the wall and CPU time, how far the pull got
# and the drag/normal ratio at 2, 5, 10, 15 and 20 mm.
# Usage (from the repository root):
#   benchmarks/calculix_drag.sh OUTDIR [meshes] [pull increments (mm)]
#                               [more deep_drag_3d_inp.py options]
# meshes "20,8,6" by default (block cells along x, y, z), increments
# "0.25". OMP_NUM_THREADS (default 1) sets CalculiX's threads; TAG, if
# set, ends the run names. The meshes of doc/contact.md's comparison are
# uniform in x and y with a z zone (softgrasp's Fine zone spanning x, y):
#   benchmarks/calculix_drag.sh OUT "20,8,3 30,12,4 40,16,6" 0.25 \
#       --fine-zone -0.04 0 -0.012 0.04 0.03 0
# (a zone inside the block in x and y works as well).
# Compare with softgrasp and plot: benchmarks/calculix/compare.py
# [--plot drag.png] ccx=<name>.csv softgrasp=<output>/drag_contact.csv.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:?usage: benchmarks/calculix_drag.sh OUTDIR [meshes] [increments] [options]}
meshes=${2:-20,8,6}
increments=${3:-0.25}
shift $(( $# < 3 ? $# : 3 ))
command -v ccx > /dev/null || {
  echo "calculix_drag.sh: 'ccx' not found. Fix: run scripts/install-dependencies.sh (package calculix-ccx)." >&2
  exit 1
}
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
mkdir -p "$out"
cd "$out"
for mesh in $meshes; do
  for increment in $increments; do
    name="ccx_${mesh//,/x}_${increment}mm${TAG:+_$TAG}"
    IFS=',' read -r nx ny nz <<< "$mesh"
    python3 "$here/calculix/deep_drag_3d_inp.py" "$nx" "$ny" "$nz" "$increment" "$@" > "$name.inp"
    /usr/bin/time -f "%e %U" -o "$name.time" ccx -i "$name" > "$name.log" 2>&1 || true
    read -r wall cpu < <(tail -n 1 "$name.time")
    python3 "$here/calculix/dat_to_csv.py" "$name.dat" > "$name.csv"
    python3 - "$name" "$wall" "$cpu" <<'PY'
import csv, sys
name, wall, cpu = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
rows = list(csv.DictReader(open(name + '.csv')))
pulled = max([float(r['pull_mm']) for r in rows] + [0.0])
def ratio(mm):
    for r in rows:
        if float(r['time']) > 1 and abs(float(r['pull_mm']) - mm) < 1e-6:
            return '%.3f' % float(r['ratio'])
    return '-'
print('%-24s wall %6.0f s  CPU %6.0f s  pulled %5.2f mm  ratio at '
      '2/5/10/15/20 mm %s' % (name, wall, cpu, pulled,
                              ' / '.join(ratio(m) for m in (2, 5, 10, 15, 20))))
PY
  done
done
