#!/usr/bin/env python3
"""The floor stamp's p(u) curve of gc2d spec 8.7 (Sec. 4.3.2, Fig. 4.32) from series.csv.

    stamp_curve.py OUTDIR [OUTDIR ...] [--wall stamp] [--png FILE]

Each OUTDIR is a run resumed from a saved pile with the stamp wall moving at a constant
velocity (run.sh). Rows before the motion have no wall_<stamp>_dy value (nan: the stamp did not
move then); the last of them gives the stamp's load at rest, P0 = -wall_<stamp>_fy [N] (the
grains push down on it). For every row of the motion:

    u = wall_<stamp>_dy [m]   (positive: pushed into the pile; negative: withdrawn)
    p = (P - P0) / P0         (P = -wall_<stamp>_fy, the relative load change of the thesis)

and the load on the other walls (their -fy summed): whatever the stamp sheds must go there.
Writes OUTDIR/stamp_curve.csv (time [s], u [m], u_over_d [1], p [1], P [N], P_others [N]), with
d the mean grain diameter from final.csv, prints the curve's landmarks, and, with matplotlib,
plots every OUTDIR's p(u/d) into one PNG (--png, default stamp_curve.png beside the first run).
Standard library only, except the optional plot.
"""
import csv
import math
import os
import sys


def curve(out, wall):
    with open(os.path.join(out, 'series.csv')) as f:
        rows = list(csv.DictReader(f))
    fy, dy = f'wall_{wall}_fy', f'wall_{wall}_dy'
    if not rows or fy not in rows[0] or dy not in rows[0]:
        raise SystemExit(f'{out}/series.csv: no columns {fy}, {dy} (is the wall named {wall} moving?)')
    others = [k for k in rows[0] if k.startswith('wall_') and k.endswith('_fy') and k != fy]
    rest = [r for r in rows if math.isnan(float(r[dy]))]
    moving = [r for r in rows if not math.isnan(float(r[dy]))]
    if not moving:
        raise SystemExit(f'{out}: the stamp never moved')
    p0 = -float((rest[-1] if rest else moving[0])[fy])
    if not p0 > 0:
        raise SystemExit(f'{out}: the stamp carries no load at rest (P0 = {p0} N)')
    with open(os.path.join(out, 'final.csv')) as f:
        radii = [float(r['radius']) for r in csv.DictReader(f)]
    d = 2 * sum(radii) / len(radii)
    points = []
    for r in moving:
        load = -float(r[fy])
        points.append({'time': float(r['time']), 'u': float(r[dy]), 'u_over_d': float(r[dy]) / d,
                       'p': (load - p0) / p0, 'P': load,
                       'P_others': -sum(float(r[k]) for k in others)})
    return p0, d, points


def landmarks(p0, d, points):
    lines = [f'P0 = {p0:.4g} N, d = {d * 1e3:.3f} mm']
    for target in (-0.5, -0.7, 0.4, 1.0):
        hit = next((q for q in points if (q['p'] <= target if target < 0 else q['p'] >= target)), None)
        lines.append(f'p = {target:+.1f} first at u = {hit["u"] * 1e6:+.1f} um ({hit["u_over_d"]:+.4f} d)'
                     if hit else f'p = {target:+.1f} not reached')
    last = points[-1]
    lines.append(f'end: u = {last["u"] * 1e6:+.1f} um ({last["u_over_d"]:+.4f} d), p = {last["p"]:+.3f}, '
                 f'load elsewhere {last["P_others"]:.4g} N (start {points[0]["P_others"]:.4g} N)')
    return lines


def main(argv):
    wall, png, outs = 'stamp', None, []
    it = iter(argv)
    for a in it:
        if a == '--wall':
            wall = next(it)
        elif a == '--png':
            png = next(it)
        else:
            outs.append(a)
    if not outs:
        raise SystemExit(__doc__)
    curves = []
    for out in outs:
        p0, d, points = curve(out, wall)
        with open(os.path.join(out, 'stamp_curve.csv'), 'w', newline='') as f:
            f.write(f'# P0 = {p0:.10g} N\n# d = {d:.10g} m\n')
            w = csv.writer(f)
            w.writerow(['time [s]', 'u [m]', 'u_over_d [1]', 'p [1]', 'P [N]', 'P_others [N]'])
            for q in points:
                w.writerow([f'{q[k]:.10g}' for k in ('time', 'u', 'u_over_d', 'p', 'P', 'P_others')])
        print(f'{out}:')
        for line in landmarks(p0, d, points):
            print('  ' + line)
        curves.append((os.path.basename(out.rstrip('/')), points))
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        print('matplotlib not found: no plot (the CSV files are written)')
        return
    fig, ax = plt.subplots(figsize=(5, 4))
    for name, points in curves:
        ax.plot([q['u_over_d'] for q in points], [q['p'] for q in points], label=name)
    ax.axhline(0, color='0.7', lw=0.5)
    ax.axvline(0, color='0.7', lw=0.5)
    ax.set_xlabel('stamp displacement u / d')
    ax.set_ylabel('p = (P - P0) / P0')
    ax.legend(fontsize=8)
    ax.set_title('floor stamp (gc2d 4.3.2)')
    fig.tight_layout()
    png = png or os.path.join(outs[0], 'stamp_curve.png')
    fig.savefig(png, dpi=120)
    print(f'plot: {png}')


if __name__ == '__main__':
    main(sys.argv[1:])
