#!/usr/bin/env python3
"""Compares drag curves of the deep 3D drag at every millimetre of pull.

Each argument is NAME=FILE: a CalculiX CSV of dat_to_csv.py or a
softgrasp contact CSV (<base>_contact.csv of frictional_drag, whose
time runs 0 to 0.5 s for the press and then 20 mm/s). The first is the
reference. Prints a Markdown table: per pull (mm) the normal force (N),
the drag (N) and their ratio of each run, and each later run's
difference from the reference in percent; then the largest differences
over the pull. With --plot FILE.png also draws the three curves of every
run over the pull with gnuplot. Usage:
  compare.py [--plot drag.png] ccx=ccx_20x8x6_0.25mm.csv sg=drag_contact.csv
"""
import csv
import os
import subprocess
import sys
import tempfile


def curve(path):
    """{pull (mm, rounded to 0.01): (normal, drag)} of one file."""
    try:
        rows = list(csv.DictReader(open(path)))
    except OSError as e:
        sys.exit('compare.py: cannot read %s (%s). Fix: give the CSV of a '
                 'finished run.' % (path, e.strerror))
    if not rows:
        sys.exit('compare.py: %s has no data rows. Fix: give the CSV of a '
                 'run that wrote at least one step.' % path)
    out = {}
    if rows and 'pull_mm' in rows[0]:
        for r in rows:
            if float(r['time']) >= 1.0 - 1e-9:
                out[round(float(r['pull_mm']), 2)] = (
                    float(r['normal_force']), float(r['drag']))
        return out
    body = [k[:-4] for k in rows[0] if k.endswith(':F_x') and '/' not in k]
    if not body:
        sys.exit('compare.py: %s has neither a pull_mm column nor a body '
                 'force column <body>:F_x. Fix: give a dat_to_csv.py CSV '
                 'or a softgrasp <base>_contact.csv.' % path)
    for r in rows:
        pull = (float(r['time']) - 0.5) * 20.0
        if pull > -1e-9:
            out[round(pull, 2)] = (float(r[body[0] + ':F_z']),
                                   -float(r[body[0] + ':F_x']))
    return out


def plot(runs, png):
    """Normal force, drag and ratio over the pull, one line per run."""
    folder = tempfile.mkdtemp()
    script = ['set terminal pngcairo size 1500,480 font ",10"',
              'set output "%s"' % png, 'set multiplot layout 1,3',
              'set xlabel "pull (mm)"', 'set grid', 'set key left top']
    for k, (name, c) in enumerate(runs):
        with open(os.path.join(folder, '%d.dat' % k), 'w') as f:
            for mm in sorted(c):
                n, d = c[mm]
                f.write('%g %g %g %g\n' % (mm, n, d, d / n if n else 0))
    for column, label in ((2, 'normal force (N)'), (3, 'drag (N)'),
                          (4, 'drag / normal force')):
        script.append('set ylabel "%s"' % label)
        script.append('plot ' + ', '.join(
            '"%s/%d.dat" using 1:%d with lines lw 2 title "%s"' % (
                folder, k, column, name.replace('_', ' '))
            for k, (name, _) in enumerate(runs)))
    subprocess.run(['gnuplot'], input='\n'.join(script), text=True,
                   check=True)


def main():
    runs = []
    args = sys.argv[1:]
    png = None
    if len(args) >= 2 and args[0] == '--plot':
        png, args = args[1], args[2:]
    for arg in args:
        name, _, path = arg.partition('=')
        if not path:
            sys.exit('compare.py: "%s" is not NAME=FILE. Fix: e.g. '
                     'ccx=run.csv.' % arg)
        runs.append((name, curve(path)))
    if len(runs) < 2:
        sys.exit(__doc__)
    head = ['pull (mm)']
    for name, _ in runs:
        head += [name + ' F_n', name + ' drag', name + ' ratio']
    for name, _ in runs[1:]:
        head += [name + ' dF_n %', name + ' ddrag %', name + ' dratio %']
    print('| ' + ' | '.join(head) + ' |')
    print('|' + '---|' * len(head))
    worst = {name: [0.0, 0.0, 0.0] for name, _ in runs[1:]}
    ref = runs[0][1]
    for mm in range(0, 21):
        if not all(mm in c for _, c in runs):
            continue
        cells = ['%d' % mm]
        for _, c in runs:
            n, d = c[mm]
            cells += ['%.3f' % n, '%.3f' % d, '%.3f' % (d / n)]
        n0, d0 = ref[mm]
        for name, c in runs[1:]:
            n, d = c[mm]
            diff = [100 * (n / n0 - 1), 100 * (d / d0 - 1) if d0 else 0.0,
                    100 * ((d / n) / (d0 / n0) - 1) if d0 else 0.0]
            if mm >= 1:   # the drag at 0 mm is zero: no relative error
                worst[name] = [max(w, abs(x)) for w, x in zip(worst[name], diff)]
            cells += ['%+.1f' % x for x in diff]
        print('| ' + ' | '.join(cells) + ' |')
    print()
    for name, w in worst.items():
        print('%s against %s, 1 to 20 mm: largest |difference| F_n %.1f %%, '
              'drag %.1f %%, ratio %.1f %%' % (name, runs[0][0], *w))
    if png:
        plot(runs, png)


if __name__ == '__main__':
    main()
