#!/usr/bin/env python3
"""Settling of a piston wall on its target force, from series.csv (issue 12).

Usage:
  python3 scripts/piston_settle.py DIR --wall NAME --target F [--direction RAD] [--band 0.01]

The force the grains exert against the piston's motion is F = -(fx, fy) . e, e = (cos a, sin a)
the piston_direction (default -pi/2, down), from the wall_<NAME>_fx/_fy columns. Printed:
the first contact (first row with F > 0), the peak force and the overshoot max F / target - 1,
the settling time (the first row after which |F / target - 1| stays below the band, 1 % by
default; counted from the first contact), and the settled force (mean over the last 10 % of
the rows) against the target. Standard library only (csv, math).
"""
import argparse
import csv
import math
import os
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--wall", required=True)
    ap.add_argument("--target", type=float, required=True, help="piston_force [N]")
    ap.add_argument("--direction", type=float, default=-math.pi / 2, help="piston_direction [rad]")
    ap.add_argument("--band", type=float, default=0.01)
    a = ap.parse_args()
    with open(os.path.join(a.dir, "series.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    fx, fy = f"wall_{a.wall}_fx", f"wall_{a.wall}_fy"
    if fx not in rows[0]:
        sys.exit(f"error: {a.dir}/series.csv has no column {fx}")
    ex, ey = math.cos(a.direction), math.sin(a.direction)
    t = [float(r["time"]) for r in rows]
    F = [-(float(r[fx]) * ex + float(r[fy]) * ey) for r in rows]
    touch = next((j for j, v in enumerate(F) if v > 0), None)
    if touch is None:
        sys.exit("error: the piston never touched the grains")
    jmax = max(range(len(F)), key=lambda j: F[j])
    settled_from = None
    for j in range(len(F) - 1, -1, -1):
        if abs(F[j] / a.target - 1) >= a.band:
            settled_from = j + 1
            break
    else:
        settled_from = 0
    tail = F[int(0.9 * len(F)):]
    Fs = sum(tail) / len(tail)
    print(f"{a.dir}: piston '{a.wall}', target {a.target:g} N, {len(F)} rows to t = {t[-1]:g} s")
    print(f"first contact      t = {t[touch]:.4f} s")
    print(f"peak force         {F[jmax]:.6f} N at t = {t[jmax]:.4f} s: overshoot {100 * (F[jmax] / a.target - 1):+.4f} %")
    if settled_from < len(F):
        print(f"settled (+-{100 * a.band:g} %) from t = {t[settled_from]:.4f} s: "
              f"{t[settled_from] - t[touch]:.4f} s after the first contact")
    else:
        print(f"not settled within +-{100 * a.band:g} % by the end of the run")
    print(f"settled force      {Fs:.6f} N (mean of the last 10 % of rows): {100 * (Fs / a.target - 1):+.4f} % of target")


if __name__ == "__main__":
    main()
