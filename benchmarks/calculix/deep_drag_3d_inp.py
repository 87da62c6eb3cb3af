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

Measured with CalculiX 2.20: C3D8I elements diverge at 8 mm of press;
with the capsule's mesh lines on its lowest line (--twist 0) ccx spins
forever in its first contact increment on some block meshes (a slave
node on a master edge), so the capsule's mesh is turned by half a cell.

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
    p.add_argument('--fine-zone', type=float, nargs=6, default=None,
                   metavar=('X0', 'Y0', 'Z0', 'X1', 'Y1', 'Z1'),
                   help='a box (m) of uniform cells, NX x NY x NZ of them; '
                        'outside it cells grow by --growth (as softgrasp\'s '
                        'Mesh/Block/Fine zone)')
    p.add_argument('--growth', type=float, default=1.3)
    p.add_argument('--slave-x', type=float, default=0.031,
                   help='top faces with |x| below it (m) are the slave '
                        'surface (the finger spans |x| < 20 mm)')
    p.add_argument('--slave-y', type=float, default=0.027,
                   help='and y below it (m) (the finger spans y < 20 mm)')
    p.add_argument('--rigid-cells', type=int, default=12,
                   help='capsule cells across each box face')
    p.add_argument('--twist', type=float, default=0.5,
                   help='turn the capsule mesh about its axis by this many '
                        'cells (0.5: no node on its lowest line)')
    p.add_argument('--element', default='C3D8',
                   help='block element type: C3D8, or C3D20R (quadratic, free of '
                        'locking; C3D8I diverges at 8 mm of press)')
    p.add_argument('--displacements', action='store_true',
                   help='write the displacements every 0.25 mm to the .frd '
                        '(for ParaView or a comparison of shapes)')
    p.add_argument('--mu', type=float, default=17241.4,
                   help='shear modulus (Pa)')
    p.add_argument('--kappa', type=float, default=166666.7,
                   help='bulk modulus (Pa): E = 50 kPa, nu = 0.45')
    p.add_argument('--friction', type=float, default=0.5,
                   help='Coulomb friction coefficient (1)')
    p.add_argument('--contact', choices=('surface', 'node'),
                   default='surface',
                   help='surface-to-surface (the default) or node-to-surface '
                        'contact')
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


def cells_to_fill(distance, h, g):
    """Cells of a progression (first size h g, ratio g) that fill distance."""
    n, total, size = 0, 0.0, h
    while total < distance * (1 - 1e-9) and n < 1000:
        size *= g
        total += size
        n += 1
    return max(n, 1)


def zoned(a, b, z0, z1, n, growth):
    """n uniform cells in [z0, z1], cells growing by growth outside it
    (softgrasp's Mesh/Block/Fine zone, mesh_generator.cc)."""
    h, tol = (z1 - z0) / n, 1e-9 * (b - a)
    x = []
    if z0 > a + tol:
        x = list(reversed(geometric(z0, a, cells_to_fill(z0 - a, h, growth),
                                    growth)))[:-1]
    x += geometric(z0, z1, n, 1.0)
    if z1 < b - tol:
        x += geometric(z1, b, cells_to_fill(b - z1, h, growth), growth)[1:]
    x[0], x[-1] = a, b
    return x


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
    lower, upper, cells = (-0.04, 0.0, -0.03), (0.04, 0.03, 0.0), (a.nx, a.ny, a.nz)
    if a.fine_zone:
        f = a.fine_zone
        xs, ys, zs = (zoned(lower[d], upper[d], f[d], f[d + 3], cells[d],
                            a.growth) for d in range(3))
    else:
        xs, ys, zs = (geometric(lower[d], upper[d], cells[d], g)
                      for d, g in enumerate((1.0, 1.0, a.grading)))
    quadratic = a.element.startswith('C3D20')
    m = 2 if quadratic else 1   # node index steps per cell

    def at(values, index):
        """Coordinate of node index (a midpoint for odd ones if quadratic)."""
        if index % m == 0:
            return values[index // m]
        return 0.5 * (values[index // m] + values[index // m + 1])

    nx, ny, nz = len(xs) - 1, len(ys) - 1, len(zs) - 1
    ids = {}
    for k in range(m * nz + 1):
        for j in range(m * ny + 1):
            for i in range(m * nx + 1):
                if not quadratic or sum(c % 2 for c in (i, j, k)) <= 1:
                    ids[i, j, k] = deck.node((at(xs, i), at(ys, j), at(zs, k)))
    top = []
    for k in range(0, m * nz, m):
        for j in range(0, m * ny, m):
            for i in range(0, m * nx, m):
                corners = [(i, j, k), (i + m, j, k), (i + m, j + m, k),
                           (i, j + m, k)]
                corners += [(p, q, r + m) for p, q, r in corners]
                c = [ids[p] for p in corners]
                if quadratic:
                    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6),
                             (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
                    c += [ids[tuple((corners[u][d] + corners[v][d]) // 2
                                    for d in range(3))] for u, v in edges]
                e = deck.element('tissue', c)
                # the slave faces: the top, where the finger can reach
                centre = [sum(deck.nodes[n - 1][d] for n in c[:8]) / 8
                          for d in range(3)]
                if k == m * (nz - 1) and abs(centre[0]) < a.slave_x and \
                        centre[1] < a.slave_y:
                    top.append(e)
    deck.nsets['BASE'] = sorted(n for (i, j, k), n in ids.items() if k == 0)
    deck.nsets['SYMMETRY'] = sorted(n for (i, j, k), n in ids.items()
                                    if j == 0)
    deck.faces['TISSUE_FACES'] = [(e, 'S2') for e in top]
    return nx * ny * nz


def capsule_point(p, radius, twist):
    """The point of the capsule of the given radius seen from the axis,
    the direction turned by twist (rad) about the axis."""
    q = (0.0, min(max(p[1], 0.0), L), 0.0)
    d = [p[i] - q[i] for i in range(3)]
    c, s = math.cos(twist), math.sin(twist)
    d = [c * d[0] + s * d[2], d[1], -s * d[0] + c * d[2]]
    n = math.sqrt(sum(c * c for c in d))
    return tuple(START[i] + q[i] + radius * d[i] / n for i in range(3))


def capsule(deck, n, twist):
    """The rigid layer: a quad grid on five faces of the box around the
    half capsule, projected onto radii R - LAYER and R, turned by twist
    (in cells) about the axis."""
    twist *= math.pi / 2 / n
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
            outer[key] = deck.node(capsule_point(p, R, twist))
            inner[key] = deck.node(capsule_point(p, R - LAYER, twist))
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
            entries = [str(number)] + [str(n) for n in c]
            # a data line holds at most 16 entries
            out.append(', '.join(entries[:16]) + (',' if len(entries) > 16 else ''))
            if len(entries) > 16:
                out.append(', '.join(entries[16:]))
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
            '*CONTACT PAIR, INTERACTION=SI, TYPE=%s TO SURFACE' % (
                'NODE' if a.contact == 'node' else 'SURFACE'),
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
                'RF']
        if a.displacements:
            out += ['*NODE FILE, NSET=NALL, TIME POINTS=%s' % points, 'U']
        out += ['*END STEP']
    print('\n'.join(out))


def main():
    a = arguments()
    deck = Deck()
    block(deck, a)
    capsule(deck, a.rigid_cells, a.twist)
    write(deck, a)


if __name__ == '__main__':
    main()
