#!/usr/bin/env bash
# Benchmark of the deep 3D frictional drag (examples/frictional_drag/
# deep_drag_3d.prm: a capsule, R = 10 mm, pressed 10 mm into a soft block
# and pulled along it, mu = 0.5) at several resolutions, on both implicit
# integrators and both contact enforcements. Prints per run the wall time,
# how far the pull got (mm), the steps, Newton and outer iterations per
# step (mean / largest), polished and unsettled steps, cut-backs, and
# drag/normal at 2 and 5 mm of pull and at the end.
# Usage (from the repository root, after building):
#   benchmarks/deep_drag_3d.sh [build-dir] [meshes] [end time (s)]
#                              [integrators] [enforcements]
# meshes "20,8,6 30,11,9 40,15,12" by default (4, 2.7 and 2 mm cells along
# the pull), end time 1.5 s (the press ends at 0.5 s, then 20 mm/s),
# integrators "quasi-static,implicit dynamic", enforcements
# "incremental potential,lagrange multipliers". Results go to
# doc/benchmarks.md by hand, with date, machine and command.
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
meshes=${2:-20,8,6 30,11,9 40,15,12}
end_time=${3:-1.5}
IFS=',' read -r -a integrators <<< "${4:-quasi-static,implicit dynamic}"
IFS=',' read -r -a enforcements <<< "${5:-incremental potential,lagrange multipliers}"
prm=$(pwd)/examples/frictional_drag/deep_drag_3d.prm
exe=$build/examples/frictional_drag/frictional_drag
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for mesh in $meshes; do
  for integrator in "${integrators[@]}"; do
    for enforcement in "${enforcements[@]}"; do
      name="${mesh//,/x}_${integrator%% *}_${enforcement%% *}"
      cp "$prm" "$name.prm"
      cat >> "$name.prm" <<EOF
subsection Mesh
  subsection Block
    set Subdivisions = ${mesh//,/, }
  end
end
subsection Contact
  set Enforcement = $enforcement
end
subsection Time
  set Integrator = $integrator
  set End time = $end_time
end
subsection Output
  set Directory = $name
  set VTU interval = 0
  set Verbose = false
end
EOF
      start=$(date +%s.%N)
      "$exe" "$name.prm" > "$name.log" 2>&1 || true
      end=$(date +%s.%N)
      wall=$(echo "$end - $start" | bc)
      /usr/bin/python3 - "$name" "$wall" <<'EOF'
import csv, glob, sys
name, wall = sys.argv[1], float(sys.argv[2])
rows = list(csv.DictReader(open(glob.glob(name + '/*_history.csv')[0])))[1:]
contact = list(csv.DictReader(open(glob.glob(name + '/*_contact.csv')[0])))
def column(key):
    return [float(r[key]) for r in rows if key in r]
def mean_max(values):
    return '%.1f / %d' % (sum(values) / len(values), max(values)) if values else '-'
def ratio_at(mm):
    # the first geom's lateral (x) and normal force at that pull
    for r in contact:
        t = float(r['time'])
        if abs((t - 0.5) * 20 - mm) < 1e-6:
            geom = [k for k in r if k.endswith(':normal_force')][0][:-13]
            return '%.3f' % (abs(float(r[geom + ':F_x'])) /
                             float(r[geom + ':normal_force']))
    return '-'
t_end = float(contact[-1]['time'])
pulled = max(0.0, (t_end - 0.5) * 20)
print('%-10s %-16s %-22s %7.0f s  to %4.1f mm  %3d steps  Newton %s  '
      'outer %s  polished %d  unsettled %d  cut-backs %d  ratio 2/5/end '
      'mm %s / %s / %s' % (
          name.split('_')[0], name.split('_')[1], name.split('_')[2], wall,
          pulled, len(rows), mean_max(column('newton_iterations')),
          mean_max(column('outer_iterations')), sum(column('polished')),
          sum(column('unsettled')), sum(column('cut_backs')), ratio_at(2),
          ratio_at(5), ratio_at(round(pulled * 2) / 2)))
EOF
    done
  done
done
