#!/usr/bin/env python3
"""Measured figures of the perturbed piles (gc2d spec 8.7) from the runs of run.sh.

    summarize.py OUT T0 [STAMP_HALF_WIDTH]

OUT holds pile/, tap_<T>/, stamp_down/, stamp_up/ and elastic/ with their `granulab analyze`
tables; T0 [s] is the time of the saved pile (where the perturbations start) and
STAMP_HALF_WIDTH [m] half the stamp's width (the stamp is centred at x = 0, run.sh).

* pile and every tap_<T>: the pile figures of ../piles/summarize.py (width, height, repose,
  coordination, interior packing, the dip test) plus the centre-of-mass height h_cm = E_pot /
  (M g) [m] at T0 and at the end (series.csv; E_pot is measured from y = 0, the floor) and the
  spread of the packing fraction: the standard deviation of rho_improved over the test areas
  below half the pile height (packing_fraction.csv; "the density homogenises" = it shrinks).
* stamp_down / stamp_up: the landmarks of stamp_curve.py, and where the load went: the change
  of the wall contacts' vertical force between the snapshots at T0 and at the end
  (vtk/contacts_N.npy), in bands of the contact's distance |x| from the stamp's centre: on the
  stamp, beside it to 3 stamp half-widths, 3-6, beyond (both sides together), in N.
* elastic: nu, E, K over the stress grid (elastic.csv): the analysis' mean +- std, and the median
  with the 25-75 % quantiles over the finite values (E and nu jump where elasticity is undefined,
  so the median is the robust figure), and the fraction of areas with u_zz > u_xx.
Standard library only.
"""
import csv
import glob
import math
import os
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import stamp_curve  # noqa: E402


def _piles_summary():
    """../piles/summarize.py (same file name as this one, so loaded by path)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location('piles_summarize', os.path.join(HERE, '..', 'piles', 'summarize.py'))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


figures = _piles_summary().figures
sys.path.insert(0, os.path.join(HERE, '..'))
from study_tables import table  # noqa: E402  (examples/studies/study_tables.py)

G = 9.81


def series(out):
    with open(os.path.join(out, 'series.csv')) as f:
        return list(csv.DictReader(f))


def com_height(out, t0):
    rows = series(out)
    at = min(rows, key=lambda r: abs(float(r['time']) - t0))
    end = rows[-1]
    h = lambda r: float(r['potential_energy']) / (float(r['mass']) * G)
    return h(at), h(end)


def snapshot_dir(out, t):
    """The analysis folder of the snapshot nearest to time t (None: the last)."""
    snaps = sorted(glob.glob(os.path.join(out, 'analysis', 'snapshot_*')))
    if t is None or not snaps:
        return snaps[-1] if snaps else None
    with open(os.path.join(out, 'snapshots.pvd')) as f:
        times = {}
        for line in f:
            if 'timestep=' in line and 'part="0"' in line:
                ts = float(line.split('timestep="')[1].split('"')[0])
                idx = line.split('file="')[1].split('"')[0].rsplit('_', 1)[1].split('.')[0]
                times[idx] = ts
    best = min(snaps, key=lambda s: abs(times.get(s.rsplit('_', 1)[1], math.inf) - t))
    return best


def packing_spread(out, f):
    snap = snapshot_dir(out, None)
    p = os.path.join(snap, 'packing_fraction.csv') if snap else ''
    if not os.path.exists(p) or 'height' not in f:
        return None
    _, rows = table(p)
    vals = [r['rho_improved'] for r in rows if r['z'] < 0.5 * f['height'] and not math.isnan(r['rho_improved'])]
    return (statistics.pstdev(vals), len(vals)) if len(vals) > 1 else None


def pile_line(out, t0):
    f = figures(out)
    if f is None:
        return f'{out}: no analysis'
    s = f"{f['run']}: {f['grains']} grains, width {f['width']:.3f} m, height {f['height']:.4f} m"
    h0, h1 = com_height(out, t0)
    s += f", h_cm {h0 * 1e3:.2f} -> {h1 * 1e3:.2f} mm ({100 * (h1 - h0) / h0:+.1f} %)"
    if 'repose' in f and f['repose'][2] is not None:
        s += f", repose {f['repose'][0]:.1f} / {f['repose'][1]:.1f} deg"
    if 'K' in f and f['K'][0] is not None:
        s += f", <K> {f['K'][0]:.2f}"
    if 'packing' in f:
        s += f", interior packing {f['packing'][0]:.3f}"
    spread = packing_spread(out, f)
    if spread:
        s += f", packing spread {spread[0]:.3f} ({spread[1]} areas)"
    if 'dip' in f:
        dip, pc, pl, pr, sigma = f['dip']
        s += f", dip {'YES' if dip else 'no'} (centre {pc:.0f}, flanks {pl:.0f} / {pr:.0f}, 2 sigma {2 * sigma:.0f} N/m)"
    return s


def wall_contacts(path):
    """(wall, px, fy) of the wall contacts in a contacts_N.npy (docs/analysis.md: a NumPy
    structured array, read here with the standard library)."""
    import ast
    import struct
    with open(path, 'rb') as f:
        data = f.read()
    if data[:6] != b'\x93NUMPY':
        raise SystemExit(f'{path}: not a .npy file')
    hlen = struct.unpack('<H', data[8:10])[0] if data[6] == 1 else struct.unpack('<I', data[8:12])[0]
    hstart = 10 if data[6] == 1 else 12
    header = ast.literal_eval(data[hstart:hstart + hlen].decode('latin1'))
    codes = {'<i8': 'q', '<i4': 'i', '<f8': 'd'}
    names = [n for n, _ in header['descr']]
    fmt = '<' + ''.join(codes[t] for _, t in header['descr'])
    size = struct.calcsize(fmt)
    body = data[hstart + hlen:]
    out = []
    for k in range(header['shape'][0]):
        rec = dict(zip(names, struct.unpack_from(fmt, body, k * size)))
        if rec['wall'] >= 0:
            out.append((rec['wall'], rec['px'], rec['fy']))
    return out


def load_shift(out, t0, half):
    """Where the load the stamp shed (or took) went: the change of the vertical wall force on the
    grains [N] between the snapshot at T0 and the last one, by contact position |x| from the
    stamp's centre: on the stamp (|x| <= half), beside it to 3 half widths, 3-6, and beyond."""
    def snapshot_file(t):
        with open(os.path.join(out, 'snapshots.pvd')) as f:
            files = [(float(line.split('timestep="')[1].split('"')[0]), line.split('file="')[1].split('"')[0])
                     for line in f if 'part="0"' in line]
        if not files:
            return None
        ts, name = min(files, key=lambda tf: abs(tf[0] - t)) if t is not None else files[-1]
        return os.path.join(out, name.replace('particles_', 'contacts_').replace('.vtp', '.npy'))

    before, after = snapshot_file(t0), snapshot_file(None)
    if not before or before == after or not os.path.exists(before) or not os.path.exists(after):
        return None

    def bands(path):
        b = [0.0, 0.0, 0.0, 0.0]
        for _, x, fy in wall_contacts(path):
            r = abs(x)
            b[0 if r <= half else 1 if r <= 3 * half else 2 if r <= 6 * half else 3] += fy
        return b

    b0, b1 = bands(before), bands(after)
    return [y - x for x, y in zip(b0, b1)]


def quantiles(v):
    v = sorted(v)
    q = lambda f: v[min(len(v) - 1, int(f * (len(v) - 1) + 0.5))]
    return q(0.25), q(0.5), q(0.75)


def main(argv):
    if len(argv) not in (2, 3):
        raise SystemExit(__doc__)
    out, t0 = argv[0], float(argv[1])
    half = float(argv[2]) if len(argv) == 3 else 0.0
    runs = ['pile'] + sorted((os.path.basename(p) for p in glob.glob(os.path.join(out, 'tap_*'))),
                             key=lambda n: float(n[4:]))
    print('-- tapping (4.3.1)')
    for r in runs:
        if os.path.isdir(os.path.join(out, r)):
            print(pile_line(os.path.join(out, r), t0))
    print('-- stamp (4.3.2)')
    for r in ('stamp_down', 'stamp_up'):
        d = os.path.join(out, r)
        if not os.path.isdir(d):
            continue
        p0, diam, points = stamp_curve.curve(d, 'stamp')
        print(f'{r}:')
        for line in stamp_curve.landmarks(p0, diam, points):
            print('  ' + line)
        if half > 0:
            shift = load_shift(d, t0, half)
            if shift:
                print(f'  wall load change by |x| from the stamp centre: {shift[0]:+.1f} N on the stamp, '
                      f'{shift[1]:+.1f} N beside it (to 3 half widths), {shift[2]:+.1f} N at 3-6, '
                      f'{shift[3]:+.1f} N beyond')
    print('-- elastic constants (4.3.3)')
    snap = snapshot_dir(os.path.join(out, 'elastic'), t0)
    p = os.path.join(snap, 'elastic.csv') if snap else ''
    if os.path.exists(p):
        notes, rows = table(p)
        nu = [r['nu'] for r in rows if math.isfinite(r['nu'])]
        E = [r['E'] for r in rows if math.isfinite(r['E'])]
        K = [r['K'] for r in rows if math.isfinite(r['K'])]
        both = [r for r in rows if math.isfinite(r['u_xx']) and math.isfinite(r['u_zz'])]
        print(f'areas with nu: {len(nu)} of {len(rows)}')
        if nu:
            a, m, b = quantiles(nu)
            print(f'nu: median {m:.3f} (quartiles {a:.3f} .. {b:.3f}); mean over finite values '
                  f'{statistics.mean(nu):.3g}')
        if E:
            a, m, b = quantiles(E)
            print(f'E:  median {m:.4g} N/m (quartiles {a:.4g} .. {b:.4g})')
        if K:
            a, m, b = quantiles(K)
            print(f'K:  median {m:.4g} N/m (quartiles {a:.4g} .. {b:.4g})')
        if both:
            up = sum(1 for r in both if r['u_zz'] > r['u_xx'])
            print(f'u_zz > u_xx in {up} of {len(both)} areas; mean u_xx {statistics.mean(r["u_xx"] for r in both):.3g}, '
                  f'u_zz {statistics.mean(r["u_zz"] for r in both):.3g}')


if __name__ == '__main__':
    main(sys.argv[1:])
