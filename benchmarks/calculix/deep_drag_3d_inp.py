#!/usr/bin/env python3
"""Writes a CalculiX input deck of softgrasp's deep 3D drag.

The same problem as examples/frictional_drag/deep_drag_3d.prm: a rigid
capsule (radius 10 mm, cylindrical part 20 mm long, its axis along y)
pressed 10 mm into a neo-Hookean block (80 x 30 x 30 mm half model,
y >= 0, mu = 17241.4 Pa, kappa = 166667 Pa with the quadratic volumetric
energy kappa/2 (J - 1)^2, i.e. CalculiX's *HYPERELASTIC, NEO HOOKE with
C10 = mu/2, D1 = 2/kappa), bonded at its base, and pulled 20 mm along x
with Coulomb friction 0.5.

CalculiX has no analytic rigid body: the capsule is a 1 mm thick layer of
stiff C3D8 elements whose every node is driven by *BOUNDARY, and whose
outer faces are the master surface of penalty surface-to-surface contact
(settings of ../shared/notes/calculix-contact.md). The capsule's surface
is meshed without poles: each face of the box [-R, R] x [0, L + R] x
[-R, R] around its half axis is projected onto the capsule from the
nearest point of the axis (a cube-sphere on the rounded end).

Every length is in metres, every stress in pascals.

Usage: deep_drag_3d_inp.py NX NY NZ PULL_INCREMENT_MM [options] > deck.inp
"""
import argparse
import math

R, L = 0.01, 0.01          # capsule radius and half length of its cylinder (m)
LAYER = 0.001              # thickness of the rigid layer (m)
START = (-0.01, 0.0, 0.0105)  # capsule centre at t = 0 (m), 0.5 mm above
DEPTH, PULL = 0.0105, 0.02    # its travel down and along x (m)


def arguments():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[1])
    p.add_argument('nx', type=int, help='block cells along x (80 mm)')
    p.add_argument('ny', type=int, help='block cells along y (30 mm)')
    p.add_argument('nz', type=int, help='block cells along z (30 mm)')
    p.add_argument('increment', type=float,
                   help='largest pull increment (mm); output every 0.25 mm')
    p.add_argument('--grading', type=float, default=0.8,
                   help='size ratio of neighbouring cells upwards in z')
    p.add_argument('--fine-x', type=float, nargs=2, default=None,
                   metavar=('X0', 'X1'),
                   help='a zone x0..x1 (m) of uniform cells, nx of them; '
                        'outside it cells grow by --growth')
    p.add_argument('--growth', type=float, default=1.3)
    p.add_argument('--rigid-cells', type=int, default=12,
                   help='capsule cells across each box face')
    p.add_argument('--element', default='C3D8',
                   help='block element type: C3D8 (C3D8I diverges at 8 mm of press)')
    p.add_argument('--mu', type=float, default=17241.4)
    p.add_argument('--kappa', type=float, default=166666.7)
    p.add_argument('--friction', type=float, default=0.5)
    p.add_argument('--stiffness', type=float, default=1e9,
                   help='contact penalty (Pa/m)')
    p.add_argument('--stick-slope', type=float, default=1e8,
                   help='friction stick slope (Pa/m)')
    return p.parse_args()


def geometric(a, b, n, ratio):
    """n cells from a to b, each ratio times the previous one."""
    w = [ratio ** k for k in range(n)]
    s, x = sum(w), [a]
    for wk in w:
        x.append(x[-1] + (b - a) * wk / s)
    x[-1] = b
    return x


def zoned(a, b, z0, z1, n, growth):
    """Uniform cells of (z1 - z0)/n in [z0, z1], growing outside it."""
    h = (z1 - z0) / n
    mid = [z0 + h * k for k in range(n + 1)]

    def grow(length):
        cells, size, total = [], h * growth, 0.0
        while total + size < length - 1e-12:
            cells.append(size)
            total += size
            size *= growth
        if cells:
            scale = length / total
            cells = [c * scale for c in cells]
        elif length > 1e-12:
            cells = [length]
        return cells

    left = [z0]
    for c in grow(z0 - a):
        left.append(left[-1] - c)
    right = list(mid)
    for c in grow(b - z1):
        right.append(right[-1] + c)
    right[-1] = b
    left[-1] = a
    return list(reversed(left))[:-1] + right


class Deck:
    """Nodes, elements and sets of the deck as they are built."""

    def __init__(self):
        self.nodes, self.elements = [], {}
        self.nsets, self.faces = {}, {}

    def node(self, x):
        self.nodes.append(x)
        return len(self.nodes)

    def element(self, kind, connectivity):
        self.elements.setdefault(kind, []).append(connectivity)
        return sum(len(v) for v in self.elements.values())


def block(deck, a):
    xs = (zoned(-0.04, 0.04, a.fine_x[0], a.fine_x[1], a.nx, a.growth)
          if a.fine_x else geometric(-0.04, 0.04, a.nx, 1.0))
    ys = geometric(0.0, 0.03, a.ny, 1.0)
    zs = geometric(-0.03, 0.0, a.nz, a.grading)
    ids = {}
    for k, z in enumerate(zs):
        for j, y in enumerate(ys):
            for i, x in enumerate(xs):
                ids[i, j, k] = deck.node((x, y, z))
    nx, ny, nz = len(xs) - 1, len(ys) - 1, len(zs) - 1
    top = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                c = [ids[i, j, k], ids[i + 1, j, k], ids[i + 1, j + 1, k],
                     ids[i, j + 1, k]]
                c += [ids[i, j, k + 1], ids[i + 1, j, k + 1],
                      ids[i + 1, j + 1, k + 1], ids[i, j + 1, k + 1]]
                e = deck.element('tissue', c)
                if k == nz - 1:
                    top.append(e)
    deck.nsets['BASE'] = [ids[i, j, 0] for j in range(ny + 1)
                          for i in range(nx + 1)]
    deck.nsets['SYMMETRY'] = [ids[i, 0, k] for k in range(nz + 1)
                              for i in range(nx + 1)]
    deck.faces['TISSUE_FACES'] = [(e, 'S2') for e in top]
    return nx * ny * nz


def capsule_point(p, radius):
    """The point of the capsule of the given radius seen from the axis."""
    q = (0.0, min(max(p[1], 0.0), L), 0.0)
    d = [p[i] - q[i] for i in range(3)]
    n = math.sqrt(sum(c * c for c in d))
    return tuple(START[i] + q[i] + radius * d[i] / n for i in range(3))


def capsule(deck, n):
    """The rigid layer: a quad grid on five faces of the box around the
    half capsule, projected onto radii R - LAYER and R."""
    across = [R * math.tan(math.pi / 4 * (2 * k / n - 1)) for k in range(n + 1)]
    n_cyl = max(2, round(n * L / (R * math.pi / 2)))
    along = [L * k / n_cyl for k in range(n_cyl)]
    along += [L + R * math.tan(math.pi / 4 * k / (n // 2))
              for k in range(n // 2 + 1)]
    faces = []
    for s in (-1, 1):   # x = -R, +R and z = -R, +R: grids in (y, other)
        faces.append([[(s * R, y, c) for c in across] for y in along])
        faces.append([[(c, y, s * R) for c in across] for y in along])
    faces.append([[(c, L + R, z) for c in across] for z in across])
    outer, inner, layer = {}, {}, []

    def ids(p):
        key = tuple(round(c * 1e9) for c in p)
        if key not in outer:
            outer[key] = deck.node(capsule_point(p, R))
            inner[key] = deck.node(capsule_point(p, R - LAYER))
        return key

    for grid in faces:
        for a in range(len(grid) - 1):
            for b in range(len(grid[0]) - 1):
                quad = [grid[a][b], grid[a + 1][b], grid[a + 1][b + 1],
                        grid[a][b + 1]]
                keys = [ids(p) for p in quad]
                x = [deck.nodes[outer[k] - 1] for k in keys]
                u = [x[1][i] - x[0][i] for i in range(3)]
                v = [x[3][i] - x[0][i] for i in range(3)]
                normal = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                          u[0] * v[1] - u[1] * v[0])
                centre = [sum(p[i] for p in x) / 4 for i in range(3)]
                radial = [centre[i] - START[i] for i in range(3)]
                radial[1] = centre[1] - min(max(centre[1], 0.0), L)
                if sum(normal[i] * radial[i] for i in range(3)) < 0:
                    keys.reverse()
                layer.append(deck.element(
                    'rigid', [inner[k] for k in keys] + [outer[k] for k in keys]))
    deck.nsets['RIGID'] = sorted(list(outer.values()) + list(inner.values()))
    deck.faces['RIGID_FACES'] = [(e, 'S2') for e in layer]


def lines(values, per_line=8):
    for k in range(0, len(values), per_line):
        yield ', '.join(str(v) for v in values[k:k + per_line])


def write(deck, a):
    out = ['** softgrasp deep 3D drag (benchmarks/calculix/deep_drag_3d_inp.py)',
           '*NODE, NSET=NALL']
    out += ['%d, %.12e, %.12e, %.12e' % ((k + 1,) + x)
            for k, x in enumerate(deck.nodes)]
    number = 0
    for name, kind in (('tissue', a.element), ('rigid', 'C3D8')):
        out.append('*ELEMENT, TYPE=%s, ELSET=E%s' % (kind, name.upper()))
        for c in deck.elements[name]:
            number += 1
            out.append('%d, ' % number + ', '.join(str(n) for n in c))
    for name, ids in deck.nsets.items():
        out.append('*NSET, NSET=%s' % name)
        out += lines(ids)
    for name, faces in deck.faces.items():
        out.append('*SURFACE, NAME=%s, TYPE=ELEMENT' % name)
        out += ['%d, %s' % f for f in faces]
    out += ['*MATERIAL, NAME=TISSUE', '*HYPERELASTIC, NEO HOOKE',
            '%.8e, %.8e' % (a.mu / 2, 2 / a.kappa),
            '*SOLID SECTION, ELSET=ETISSUE, MATERIAL=TISSUE',
            '*MATERIAL, NAME=RIGID', '*ELASTIC', '2.1e11, 0.3',
            '*SOLID SECTION, ELSET=ERIGID, MATERIAL=RIGID',
            '*SURFACE INTERACTION, NAME=SI',
            '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR',
            '%g' % a.stiffness, '*FRICTION', '%g, %g' % (a.friction, a.stick_slope),
            '*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE',
            'TISSUE_FACES, RIGID_FACES',
            '*BOUNDARY', 'BASE, 1, 3', 'SYMMETRY, 2, 2']
    # output every 0.25 mm of travel: 0.1 of the press step's time
    press_points = [0.05 * k for k in range(1, 21)]
    pull_points = [0.0125 * k for k in range(1, 81)]
    for name, points in (('TPRESS', press_points), ('TPULL', pull_points)):
        out.append('*TIME POINTS, NAME=%s' % name)
        out += lines(['%.6f' % t for t in points])
    steps = (('TPRESS', 0.0, 0.05), ('TPULL', PULL, a.increment / 20.0))
    for points, dx, dt in steps:
        out += ['*STEP, NLGEOM, INC=100000', '*STATIC',
                '%g, 1.0, 1e-7, %g' % (min(0.02, dt), dt),
                '*CONTROLS, PARAMETERS=TIME INCREMENTATION',
                '8, 10, 9, 50, 10, 4, 0, 15',
                '*BOUNDARY', 'RIGID, 1, 1, %.9g' % dx, 'RIGID, 2, 2, 0',
                'RIGID, 3, 3, %.9g' % -DEPTH,
                '*NODE PRINT, NSET=RIGID, TOTALS=ONLY, TIME POINTS=%s' % points,
                'RF',
                '*NODE PRINT, NSET=BASE, TOTALS=ONLY, TIME POINTS=%s' % points,
                'RF', '*END STEP']
    print('\n'.join(out))


def main():
    a = arguments()
    deck = Deck()
    block(deck, a)
    capsule(deck, a.rigid_cells)
    write(deck, a)


if __name__ == '__main__':
    main()
