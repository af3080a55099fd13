#!/usr/bin/env python3
"""Fit Beverloo's 2D law W = C rho_b sqrt(g) (D - k d)^(3/2) to silo discharge runs (issue 12).

Usage:
  python3 scripts/beverloo_fit.py DIR [DIR ...] [--widths D1,D2,...] [--outlet orifice]
                                  [--skip 0.1] [--window xmin,ymin,xmax,ymax] [--g 9.81]

Each DIR is the output folder of a run of examples/machines/silo_discharge.toml (series.csv,
final.csv). For every run:
  W     the steady mass flow [kg/s per m depth]: least-squares slope of outlet_<name>_mass
        against time, from (opening time + skip) to the end of the run. The opening time is the
        first row with a removal.
  D     the orifice width: --widths (same order as the folders), else read from the folder
        name "..._D<mm>" (silo_D30 -> 0.030 m).
  d     mean particle diameter, rho_p the particle areal density (mass / pi r^2), both from
        final.csv.
  phi   packing fraction: disk area of the final.csv particles whose centres lie in the window
        (default: two side strips of the 20 cm silo, away from the flowing zone) / window area.
rho_b = phi rho_p. The fit is linear in W^(2/3): W^(2/3) = (C rho_b sqrt(g))^(2/3) (D - k d),
so slope s and intercept i give k = -i / (s d) and C = s^(3/2) / (rho_b sqrt(g)), with rho_b
and d the means over the runs. With one run only W, phi and rho_b are printed.
Standard library only (csv, math): runs wherever python3 does.
"""
import argparse
import csv
import math
import os
import re
import sys



def polyfit1(x, y):
    """Least-squares line y = s x + i (standard library only: numpy is not required)."""
    n = len(x)
    mx = sum(x) / n
    my = sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    sxy = sum((a - mx) * (b - my) for a, b in zip(x, y))
    s = sxy / sxx
    return s, my - s * mx


def read_series(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"error: {path}: no rows")
    return rows


def steady_flow(folder, outlet, skip):
    rows = read_series(os.path.join(folder, "series.csv"))
    col = f"outlet_{outlet}_mass"
    if col not in rows[0]:
        names = [k for k in rows[0] if k.startswith("outlet_") and k.endswith("_mass")]
        sys.exit(f"error: {folder}/series.csv has no column {col}; outlets: {names}")
    t = [float(r["time"]) for r in rows]
    m = [float(r[col]) for r in rows]
    opened = [j for j, v in enumerate(m) if v > 0.0]
    if not opened:
        sys.exit(f"error: {folder}: nothing left through outlet '{outlet}'")
    t_open = t[max(opened[0] - 1, 0)]
    sel = [j for j, v in enumerate(t) if v >= t_open + skip]
    if len(sel) < 3:
        sys.exit(f"error: {folder}: fewer than 3 rows after t_open + skip = {t_open + skip:g} s")
    ts = [t[j] for j in sel]
    ms = [m[j] for j in sel]
    slope, intercept = polyfit1(ts, ms)
    rms = math.sqrt(sum((b - (slope * a + intercept)) ** 2 for a, b in zip(ts, ms)) / len(ts))
    return slope, t_open, ts[0], ts[-1], rms


def particles(folder):
    with open(os.path.join(folder, "final.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return [(float(q["x"]), float(q["y"]), float(q["radius"]), float(q["mass"])) for q in rows]


def packing(parts, windows):
    area = 0.0
    covered = 0.0
    for (x0, y0, x1, y1) in windows:
        area += (x1 - x0) * (y1 - y0)
        covered += sum(math.pi * r * r for (x, y, r, _) in parts if x0 <= x < x1 and y0 <= y < y1)
    return covered / area


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("--widths", help="orifice widths D [m], comma separated, one per folder")
    ap.add_argument("--outlet", default="orifice")
    ap.add_argument("--skip", type=float, default=0.1, help="seconds after opening left out [s]")
    ap.add_argument("--window", action="append",
                    help="xmin,ymin,xmax,ymax of a packing-fraction window (repeatable)")
    ap.add_argument("--g", type=float, default=9.81)
    a = ap.parse_args()

    if a.widths:
        widths = [float(v) for v in a.widths.split(",")]
        if len(widths) != len(a.dirs):
            sys.exit("error: --widths needs one width per folder")
    else:
        widths = []
        for d in a.dirs:
            mt = re.search(r"_D(\d+(?:\.\d+)?)", os.path.basename(os.path.normpath(d)))
            if not mt:
                sys.exit(f"error: no width for {d}: name it ..._D<mm> or give --widths")
            widths.append(float(mt.group(1)) * 1e-3)
    windows = [tuple(float(v) for v in w.split(",")) for w in a.window] if a.window else \
        [(0.005, 0.01, 0.06, 0.08), (0.14, 0.01, 0.195, 0.08)]

    W, rho_b, dmean = [], [], []
    print(f"{'run':<28} {'D [m]':>8} {'W [kg/s/m]':>11} {'fit window [s]':>15} {'rms [kg]':>9} "
          f"{'phi':>6} {'rho_b':>7} {'d [m]':>9}")
    for folder, D in zip(a.dirs, widths):
        w, t_open, t0, t1, rms = steady_flow(folder, a.outlet, a.skip)
        parts = particles(folder)
        rho_p = sum(m / (math.pi * r * r) for (_, _, r, m) in parts) / len(parts)
        phi = packing(parts, windows)
        W.append(w)
        rho_b.append(phi * rho_p)
        dmean.append(sum(2.0 * r for (_, _, r, _) in parts) / len(parts))
        print(f"{os.path.basename(os.path.normpath(folder)):<28} {D:8.4f} {w:11.5f} "
              f"{t0:7.3f}-{t1:<7.3f} {rms:9.2e} {phi:6.3f} {phi * rho_p:7.3f} {dmean[-1]:9.2e}")

    if len(W) < 2:
        return
    rb = sum(rho_b) / len(rho_b)
    d = sum(dmean) / len(dmean)
    Dv = widths
    s, i = polyfit1(Dv, [w ** (2.0 / 3.0) for w in W])
    k = -i / (s * d)
    C = s ** 1.5 / (rb * math.sqrt(a.g))
    pred = [C * rb * math.sqrt(a.g) * max(D - k * d, 0.0) ** 1.5 for D in Dv]
    print(f"Beverloo 2D fit over {len(W)} widths: C = {C:.3f}, k = {k:.3f} "
          f"(rho_b = {rb:.3f} kg/m^2, d = {d * 1e3:.3f} mm, g = {a.g} m/s^2)")
    for D, w, p in zip(Dv, W, pred):
        print(f"  D = {D:.4f} m: W = {w:.5f}, fit {p:.5f} ({(p / w - 1) * 100:+.1f} %)")


if __name__ == "__main__":
    main()
