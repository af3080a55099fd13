#!/usr/bin/env python3
"""Measured crater figures from run folders and their `granulab analyze` tables, one line each.

    summarize.py OUTDIR [OUTDIR ...]

Per run (run.sh names them SERIES_kK, K = k_coh in N/m, and `clog`):
  * removed: grains that left through the outlet (series.csv outlet_orifice_removed, last row),
    and the grains left in the box;
  * over: grains at rest (slower than 1 cm/s) with their centre over the outlet at the end
    (final.csv);
  * flow: `drains` while the removed count still rises over the last 0.05 s of the run;
    `clogged` when it has not changed for 0.05 s and the resting grains bridge the outlet (every
    strip one mean diameter wide over it holds one: a plug); `done` when it stopped without a
    bridge (the crater is open and its walls rest). A run with a [[change]] (clog) prints the
    removed counts at the outlet opening, at the change and at the end, and whether the flow
    restarted (removed rises after the change);
  * repose A / B: the integral method tan(phi) = 2a/b^2 over each residual slope (the notes
    repose_range_1_deg / repose_range_2_deg of repose_profile.csv, from --range);
  * <K>: mean coordination with and without rattlers (coordination.csv, walls counted);
  * persistence: the fraction of grain pairs in contact when the outlet opened that are still in
    contact at the end, among the grains in region C (contact_persistence.csv);
  * roughness: rms deviation of A and B from their fitted lines, and the power in the two lowest
    wavenumbers (large clusters) against the rest (roughness_spectrum.csv).
Standard library only (no numpy), so any python3 runs it.
"""
import csv
import glob
import math
import os
import re
import sys


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
from study_tables import table as notes_rows  # noqa: E402  (examples/studies/study_tables.py)


def scene_value(scene, section, key):
    """First `key = number` inside the first [[section]] / [section] of a scene file."""
    inside = False
    with open(scene) as f:
        for line in f:
            s = line.split('#', 1)[0].strip()
            if s.startswith('['):
                inside = s.strip('[]') == section
                continue
            m = re.match(r'(\w+)\s*=\s*([-+0-9.eE]+)$', s)
            if inside and m and m.group(1) == key:
                return float(m.group(2))
    return None


def series(out):
    with open(os.path.join(out, 'series.csv')) as f:
        return [(float(r['time']), int(float(r['outlet_orifice_removed'])), int(float(r['particles'])))
                for r in csv.DictReader(f)]


def removed_at(ser, t):
    best = ser[0]
    for row in ser:
        if row[0] <= t + 1e-9:
            best = row
    return best[1]


def stalled_for(ser, t_end, t_open):
    """How long the removed count has been constant up to t_end [s], since the outlet opened."""
    rows = [r for r in ser if t_open - 1e-9 <= r[0] <= t_end + 1e-9]
    last = rows[-1][1]
    t0 = rows[-1][0]
    for r in reversed(rows):
        if r[1] != last:
            break
        t0 = r[0]
    return rows[-1][0] - t0


def figures(out):
    f = {'run': os.path.basename(out.rstrip('/'))}
    with open(os.path.join(out, 'summary.json')) as fh:
        text = fh.read()
    m = re.search(r'"scene"\s*:\s*"([^"]+)"', text)
    scene = m.group(1) if m else None
    m = re.search(r'_k([0-9.e+-]+)$', f['run'])
    f['k'] = float(m.group(1)) if m else (scene_value(scene, 'contact', 'cohesion') if scene else None)
    ser = series(out)
    open_at = (scene_value(scene, 'outlet', 'open_at') if scene else None) or 0.0
    change_at = scene_value(scene, 'change', 'at') if scene else None
    edge = None
    with open(scene) as fh:
        m = re.search(r'edge\s*=\s*\[\[\s*([-0-9.e]+)\s*,[^\]]*\]\s*,\s*\[\s*([-0-9.e]+)', fh.read())
        if m:
            edge = abs(float(m.group(1)) - float(m.group(2))) / 2
    with open(os.path.join(out, 'final.csv')) as fh:
        g = list(csv.DictReader(fh))
    f['left'] = len(g)
    # Resting grains over the outlet, and whether they bridge it: every strip one mean diameter
    # wide over the outlet holds one (a plug; cliffs at the outlet's edges leave strips empty).
    f['over'], f['bridge'] = 0, False
    if edge and g:
        d = 2 * sum(float(r['radius']) for r in g) / len(g)
        strips = max(1, int(round(2 * edge / d)))
        hit = [False] * strips
        for r in g:
            x, y = float(r['x']), float(r['y'])
            if abs(x) < edge and y > 0 and math.hypot(float(r['vx']), float(r['vy'])) < 0.01:
                f['over'] += 1
                hit[min(strips - 1, int((x + edge) / (2 * edge) * strips))] = True
        f['bridge'] = all(hit)
    t_end = ser[-1][0]
    f['removed'] = ser[-1][1]
    window = 0.05

    def state(t):
        if stalled_for(ser, t, open_at) < window:
            return 'drains'
        return 'clogged' if f['bridge'] else 'done'

    if change_at is not None and change_at < t_end:
        f['flow'] = 'removed %d at open (%.3g s), %d at change (%.3g s; stalled %.3g s), %d at end' % (
            removed_at(ser, open_at), open_at, removed_at(ser, change_at), change_at,
            stalled_for(ser, change_at, open_at), f['removed'])
        f['restart'] = f['removed'] > removed_at(ser, change_at)
    else:
        f['flow'] = state(t_end)
    snaps = sorted(glob.glob(os.path.join(out, 'analysis', 'snapshot_*')))
    if not snaps:
        return f
    snap = snaps[-1]
    n, _ = notes_rows(os.path.join(snap, 'repose_profile.csv'))
    f['repose'] = [n[k] for k in ('repose_range_1_deg', 'repose_range_2_deg') if k in n]
    n, _ = notes_rows(os.path.join(snap, 'coordination.csv'))
    f['K'] = (n.get('mean_K', math.nan), n.get('mean_K_nonrattler', math.nan))
    n, rows = notes_rows(os.path.join(snap, 'contact_persistence.csv'))
    f['persist'] = n.get('persistence_fraction', math.nan)
    f['pairs'] = (int(rows[0]['pairs_before']), int(rows[0]['pairs_kept'])) if rows else (0, 0)
    n, rows = notes_rows(os.path.join(snap, 'roughness_spectrum.csv'))
    f['rms'] = n.get('rms_deviation', math.nan)
    p = [r['P'] for r in rows]
    f['p_low'] = sum(p[:2]) if p else math.nan
    f['p_high'] = sum(p[2:]) if p else math.nan
    return f


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    print('%-14s %8s %6s %5s %5s %-9s %13s %13s %12s %9s %9s %9s' % (
        'run', 'k_coh', 'remov', 'left', 'over', 'flow', 'repose A/B', '<K> all/nr', 'persist C',
        'rms [mm]', 'P_low', 'P_high'))
    for out in argv[1:]:
        f = figures(out)
        rep = f.get('repose', [])
        reps = '/'.join('%.1f' % r for r in rep) if rep else '-'
        k = f.get('K', (math.nan, math.nan))
        pairs = f.get('pairs', (0, 0))
        flow = f['flow'] if 'restart' not in f else ('restart' if f['restart'] else 'no restart')
        print('%-14s %8.3g %6d %5d %5d %-9s %13s %13s %12s %9.3g %9.2e %9.2e' % (
            f['run'], f['k'] if f['k'] is not None else math.nan, f['removed'], f['left'], f['over'],
            flow, reps, '%.2f/%.2f' % k, '%.3f(%d/%d)' % (f.get('persist', math.nan), pairs[1], pairs[0]),
            1e3 * f.get('rms', math.nan), f.get('p_low', math.nan), f.get('p_high', math.nan)))
        if 'restart' in f:
            print('    %s' % f['flow'])
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
