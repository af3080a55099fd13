#!/usr/bin/env python3
"""Angle of repose of the free surface of a granular bed (issue 12).

Usage:
  python3 scripts/repose_angle.py DIR [--centre X,Y] [--half-width H] [--bin B]

Reads DIR/final.csv. The free surface is sampled by the top of the highest particle
(y + radius) in each vertical bin of width B (default: 2 mean diameters) over
|x - X| <= H (default: the whole bed, less 3 diameters at each end: keep away from the walls);
a least-squares line through these points gives the angle atan(slope) in degrees (positive:
the surface rises to the right). For a drum give its centre and a half-width of ~0.7 R.
Standard library only (csv, math).
"""
import argparse
import csv
import math
import os
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--centre", default=None, help="X,Y: centre of the sampled x range [m]")
    ap.add_argument("--half-width", type=float, default=None, help="H [m]")
    ap.add_argument("--bin", type=float, default=None, help="bin width B [m]")
    a = ap.parse_args()

    with open(os.path.join(a.dir, "final.csv"), newline="") as f:
        parts = [(float(r["x"]), float(r["y"]), float(r["radius"])) for r in csv.DictReader(f)]
    if len(parts) < 10:
        sys.exit(f"error: {a.dir}/final.csv: too few particles ({len(parts)})")
    d = 2.0 * sum(p[2] for p in parts) / len(parts)
    B = a.bin if a.bin else 2.0 * d
    if a.centre:
        xc = float(a.centre.split(",")[0])
        H = a.half_width if a.half_width else 0.5 * (max(p[0] for p in parts) - min(p[0] for p in parts))
    else:
        lo = min(p[0] for p in parts) + 3 * d
        hi = max(p[0] for p in parts) - 3 * d
        xc = 0.5 * (lo + hi)
        H = a.half_width if a.half_width else 0.5 * (hi - lo)
    nb = max(int(2 * H / B), 2)
    tops = {}
    for x, y, r in parts:
        k = int(math.floor((x - (xc - H)) / B))
        if 0 <= k < nb and (k not in tops or y + r > tops[k][1]):
            tops[k] = (x, y + r)
    pts = sorted(tops.values())
    if len(pts) < 3:
        sys.exit("error: fewer than 3 surface points")
    n = len(pts)
    mx = sum(p[0] for p in pts) / n
    my = sum(p[1] for p in pts) / n
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    s = sxy / sxx
    rms = math.sqrt(sum((p[1] - my - s * (p[0] - mx)) ** 2 for p in pts) / n)
    # standard error of the slope -> of the angle
    se = math.sqrt(sum((p[1] - my - s * (p[0] - mx)) ** 2 for p in pts) / max(n - 2, 1) / sxx)
    ang = math.degrees(math.atan(s))
    dang = math.degrees(se / (1 + s * s))
    print(f"{a.dir}: {n} surface points over x in [{xc - H:.4f}, {xc + H:.4f}] m (bins {B * 1e3:.2f} mm), "
          f"d = {d * 1e3:.2f} mm")
    print(f"angle of repose = {ang:.1f} deg +- {dang:.1f} (slope {s:.4f}, rms off the line "
          f"{rms * 1e3:.2f} mm = {rms / d:.2f} d)")


if __name__ == "__main__":
    main()
