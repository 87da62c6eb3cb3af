#!/usr/bin/env bash
# Benchmark of mesh links (issue 54): the shipped squeezed_ball.prm (a
# rubber ball squeezed by a rigid box plate) with the plate as its analytic
# box and as the same box made of 4800 triangles (an OBJ file written here,
# each face 20 x 20 cells of two triangles), run in turn; prints each run's
# plate force, the 'contact' timer (search and nodal conditions, every
# contact update of the run) and the total wall time. Then the query alone:
# benchmarks/mesh_link_query (a 4800-triangle box against a capsule).
# Usage (from the repository root, after building):
#   benchmarks/mesh_link.sh [build-dir] [rounds]
# Results go to doc/benchmarks.md by hand, with date, machine and command.
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
rounds=${2:-3}
work=$build/benchmarks/mesh_link
mkdir -p "$work" && cd "$work"
python3 - <<'PY'
k, h = 20, (0.03, 0.03, 0.005)
index, vertices, faces = {}, [], []
def vertex(p):
    if p not in index:
        index[p] = len(vertices) + 1
        vertices.append(tuple((2.0 * p[i] / k - 1) * h[i] for i in range(3)))
    return index[p]
for axis in range(3):
    a, b = (axis + 1) % 3, (axis + 2) % 3
    for side in (0, k):
        for i in range(k):
            for j in range(k):
                q = []
                for c in range(4):
                    p = [0, 0, 0]
                    p[axis], p[a], p[b] = side, i + (c in (1, 2)), j + (c >= 2)
                    q.append(vertex(tuple(p)))
                faces.append(q if side == k else [q[0], q[3], q[2], q[1]])
with open("slab.obj", "w") as out:
    out.writelines("v %.17g %.17g %.17g\n" % v for v in vertices)
    out.writelines("f %d %d %d %d\n" % tuple(q) for q in faces)
PY
prm=$(dirname "$0")/../programs/softgrasp/squeezed_ball.prm
[ -f "$prm" ] || prm=$build/../programs/softgrasp/squeezed_ball.prm
sed 's/squeezed_ball_output/box_output/' "$prm" > box.prm
sed -e 's/      set Type             = box/      set Type             = mesh\n      set Mesh file        = slab.obj/' \
    -e 's/squeezed_ball_output/mesh_output/' "$prm" > mesh.prm
for round in $(seq "$rounds"); do
  for plate in box mesh; do
    "$build/programs/softgrasp/softgrasp" $plate.prm > $plate.log 2>&1
    echo "$plate: $(grep -m1 -o 'normal force [0-9.e+-]* N' $plate.log)," \
      "contact$(grep '^| contact' $plate.log | awk -F'|' '{print $4}')," \
      "total$(grep 'Total wallclock' $plate.log | awk -F'|' '{print $3}')"
  done
done
"$build/benchmarks/mesh_link_query"
