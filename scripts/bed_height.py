#!/usr/bin/env python3
"""Bed height and packing fraction against time from series.csv (issue 12, tapped box).

Usage:
  python3 scripts/bed_height.py DIR --width L [--floor Y0] [--every N]

For a bed of uniform density on a floor at y = Y0 in a box of width L, the mean centre height is
h/2 above the floor, so h = 2 (PE / (M g) - Y0) with PE the potential_energy column of
series.csv (reference y = 0), M the total mass and g the gravity (both from final.csv and
summary.json's scene; g = 9.81 unless --g). The packing fraction is phi = A_disks / (L h)
with A_disks the disk area of final.csv. The floor's vibration displacement
(wall_<name>_dy) is ignored: take rows at the calm phase of the vibration.
Standard library only (csv, math).
"""
import argparse
import csv
import math
import os


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--width", type=float, required=True, help="box width L [m]")
    ap.add_argument("--floor", type=float, default=0.0, help="floor height Y0 [m]")
    ap.add_argument("--g", type=float, default=9.81)
    ap.add_argument("--every", type=int, default=4, help="print every N-th row")
    a = ap.parse_args()
    with open(os.path.join(a.dir, "final.csv"), newline="") as f:
        parts = [(float(r["radius"]), float(r["mass"])) for r in csv.DictReader(f)]
    M = sum(p[1] for p in parts)
    A = sum(math.pi * p[0] ** 2 for p in parts)
    with open(os.path.join(a.dir, "series.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    out = []
    for r in rows:
        h = 2.0 * (float(r["potential_energy"]) / (M * a.g) - a.floor)
        out.append((float(r["time"]), h, A / (a.width * h), float(r["kinetic_energy"])))
    print(f"{'t [s]':>7} {'h [mm]':>8} {'phi':>7} {'E_kin [J]':>10}")
    for j, (t, h, phi, ek) in enumerate(out):
        if j % a.every == 0 or j == len(out) - 1:
            print(f"{t:7.3f} {h * 1e3:8.3f} {phi:7.4f} {ek:10.2e}")


if __name__ == "__main__":
    main()
