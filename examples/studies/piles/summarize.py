#!/usr/bin/env python3
"""Measured pile figures from a run folder and its `granulab analyze` tables, one line each.

    summarize.py OUTDIR [OUTDIR ...]

Per run (last snapshot): grains; width and height of the pile from final.csv (extent of the
grains' circumcircles, so up to one radius too large on each side); angle of repose (left,
right, mean; repose_profile.csv); mean coordination with and without rattlers
(coordination.csv); median interior packing fraction (packing_fraction.csv, test areas whose
centre lies below half the pile height and inside the middle half of the width: the interior,
away from the surface band); and the dip test on floor_pressure.csv:

  p_c  = min of the moving average p_avg within +-0.1 d of the pile centre (d = pile width),
  p_L, p_R = max of p_avg on each side between 0.1 d and 0.4 d from the centre,
  sigma = standard deviation of p - p_avg over the windows inside the pile (the window-to-window
          fluctuation of one window; a moving average over M windows is less noisy, so this is
          conservative),
  dip   = min(p_L, p_R) - p_c > 2 sigma.
Standard library only (no numpy), so any python3 runs it.
"""
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
from study_tables import table  # noqa: E402  (examples/studies/study_tables.py)


def figures(out):
    snaps = sorted(glob.glob(os.path.join(out, 'analysis', 'snapshot_*')))
    if not snaps:
        return None
    snap = snaps[-1]
    f = {'run': os.path.basename(out.rstrip('/'))}
    with open(os.path.join(out, 'final.csv')) as fh:
        g = list(csv.DictReader(fh))
    xs = [float(r['x']) for r in g]
    ys = [float(r['y']) for r in g]
    rs = [float(r['radius']) for r in g]
    f['grains'] = len(g)
    if g:
        f['width'] = max(x + r for x, r in zip(xs, rs)) - min(x - r for x, r in zip(xs, rs))
        f['height'] = max(y + r for y, r in zip(ys, rs))
        xc = 0.5 * (max(xs) + min(xs))
    p = os.path.join(snap, 'repose_profile.csv')
    if os.path.exists(p):
        n, _ = table(p)
        f['repose'] = (n.get('repose_left_deg'), n.get('repose_right_deg'), n.get('repose_mean_deg'))
    p = os.path.join(snap, 'coordination.csv')
    if os.path.exists(p):
        n, _ = table(p)
        f['K'] = (n.get('mean_K'), n.get('mean_K_nonrattler'))
    p = os.path.join(snap, 'packing_fraction.csv')
    if os.path.exists(p) and g:
        _, rows = table(p)
        inner = sorted(r['rho_improved'] for r in rows
                       if abs(r['x'] - xc) < 0.25 * f['width'] and r['z'] < 0.5 * f['height']
                       and not math.isnan(r['rho_improved']))
        if inner:
            f['packing'] = (inner[len(inner) // 2], len(inner))
    p = os.path.join(snap, 'floor_pressure.csv')
    if os.path.exists(p) and g:
        _, rows = table(p)
        d = f['width']
        inside = [r for r in rows if abs(r['x'] - xc) < 0.4 * d and not math.isnan(r['p'])]
        cen = [r['p_avg'] for r in inside if abs(r['x'] - xc) <= 0.1 * d]
        left = [r['p_avg'] for r in inside if -0.4 * d <= r['x'] - xc < -0.1 * d]
        right = [r['p_avg'] for r in inside if 0.1 * d < r['x'] - xc <= 0.4 * d]
        res = [r['p'] - r['p_avg'] for r in inside]
        if cen and left and right and len(res) > 2:
            mean = sum(res) / len(res)
            sigma = math.sqrt(sum((v - mean) ** 2 for v in res) / (len(res) - 1))
            pc, pl, pr = min(cen), max(left), max(right)
            f['dip'] = (min(pl, pr) - pc > 2 * sigma, pc, pl, pr, sigma)
    return f


def fmt(v, spec):
    return 'n/a' if v is None else format(v, spec)


def main(argv):
    for out in argv:
        f = figures(out)
        if f is None:
            print(f'{out}: no analysis (run granulab analyze first)')
            continue
        line = f"{f['run']}: {f['grains']} grains"
        if 'width' in f:
            line += f", width {f['width']:.3f} m, height {f['height']:.3f} m"
        if 'repose' in f:
            l, r, m = f['repose']
            line += f", repose {fmt(l, '.1f')} / {fmt(r, '.1f')} (mean {fmt(m, '.1f')}) deg"
        if 'K' in f:
            line += f", <K> {fmt(f['K'][0], '.2f')} (no rattlers {fmt(f['K'][1], '.2f')})"
        if 'packing' in f:
            line += f", interior packing {f['packing'][0]:.3f} ({f['packing'][1]} areas)"
        if 'dip' in f:
            dip, pc, pl, pr, s = f['dip']
            line += (f", dip {'YES' if dip else 'no'} (centre {pc:.0f}, flanks {pl:.0f} / {pr:.0f},"
                     f" 2 sigma {2 * s:.0f} N/m)")
        print(line)


if __name__ == '__main__':
    main(sys.argv[1:])
