#!/usr/bin/env python3
"""Reads the force totals of a CalculiX run of deep_drag_3d_inp.py (its
.dat file) and writes them as CSV: per output time, the finger's travel
(press, then pull, in mm), the force of the tissue on the finger (N, the
negative of the reaction at the rigid layer's driven nodes), its normal
(+z) and drag (-x) parts and their ratio, and the base's reactions with
their imbalance against the finger's (N; the y plane is a symmetry plane,
so only x and z balance).

Usage: dat_to_csv.py run.dat > run.csv
"""
import re
import sys


def records(path):
    """(set name, time, force) per total in the file, in order."""
    try:
        text = open(path).read()
    except OSError as e:
        sys.exit('dat_to_csv.py: cannot read %s (%s). Fix: give the .dat '
                 'file of a CalculiX run of deep_drag_3d_inp.py.' % (
                     path, e.strerror))
    pattern = re.compile(r'total force \(fx,fy,fz\) for set (\S+) and time\s+'
                         r'(\S+)\s+(\S+)\s+(\S+)\s+(\S+)')
    for m in pattern.finditer(text):
        yield m.group(1), float(m.group(2)), [float(m.group(k))
                                              for k in (3, 4, 5)]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    rows, offset, last = {}, 0.0, 0.0
    for name, t, f in records(sys.argv[1]):
        if t + offset < last - 1e-9:   # a step that restarts its time
            offset += 1.0
        t += offset
        last = t
        rows.setdefault(round(t, 9), {})[name] = f
    print('time,press_mm,pull_mm,normal_force,drag,ratio,'
          'base_F_x,base_F_z,imbalance_x,imbalance_z')
    for t in sorted(rows):
        r = rows[t]
        if 'RIGID' not in r or 'BASE' not in r:
            continue
        finger = [-c for c in r['RIGID']]
        base = r['BASE']
        normal, drag = finger[2], -finger[0]
        press = 10.5 * min(t, 1.0)
        pull = 20.0 * max(t - 1.0, 0.0)
        ratio = drag / normal if normal > 0 else 0.0
        print('%.6f,%.4f,%.4f,%.8g,%.8g,%.6f,%.8g,%.8g,%.3g,%.3g' % (
            t, press, pull, normal, drag, ratio, base[0], base[2],
            base[0] - finger[0], base[2] - finger[2]))


if __name__ == '__main__':
    main()
