#!/usr/bin/env python3
"""Particle-flow checks from series.csv (issue 12): inserted = rate x T, and the mass balance.

Usage:
  python3 scripts/flow_balance.py DIR [--rate R] [--from T0]

Prints the final counters (particles, inserted, skipped, removed, per outlet), compares the
inserted count with R (t_end - T0) when --rate is given, and checks
mass(t) = mass(0) + mass_in(t) - mass_out(t) at every row (largest deviation, absolute and
relative to the mass). Exit status 1 when a check fails. Standard library only (csv).
"""
import argparse
import csv
import os
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--rate", type=float, default=None, help="inlet rate [1/s] (all inlets together)")
    ap.add_argument("--from", dest="t0", type=float, default=0.0, help="start of emission [s]")
    a = ap.parse_args()
    with open(os.path.join(a.dir, "series.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if "mass_in" not in rows[0]:
        sys.exit(f"error: {a.dir}/series.csv has no flow columns (no source, inlet or outlet)")
    last = rows[-1]
    T = float(last["time"])
    ok = True
    print(f"{a.dir}: t = {T:g} s, particles {last['particles']}, inserted {last['inserted']}, "
          f"skipped {last['skipped']}, removed {last['removed']}")
    for k in rows[0]:
        if k.startswith("outlet_") and k.endswith("_removed"):
            name = k[len("outlet_"):-len("_removed")]
            print(f"  outlet {name}: removed {last[k]}, mass {float(last['outlet_' + name + '_mass']):.6g} kg")
    if a.rate is not None:
        expect = a.rate * (T - a.t0)
        ins = int(last["inserted"])
        good = abs(ins - expect) < 1.0
        ok &= good
        print(f"inserted {ins} vs rate x T = {a.rate:g} x {T - a.t0:g} = {expect:g}: {'ok' if good else 'MISMATCH'}")
    m0 = float(rows[0]["mass"])
    worst, worst_rel, at = 0.0, 0.0, 0.0
    for r in rows:
        m = float(r["mass"])
        dev = abs(m - (m0 + float(r["mass_in"]) - float(r["mass_out"])))
        if dev > worst:
            worst, at = dev, float(r["time"])
            worst_rel = dev / max(m, 1e-300)
    good = worst_rel < 1e-9
    ok &= good
    print(f"mass balance over {len(rows)} rows: max |mass - (mass(0) + mass_in - mass_out)| = "
          f"{worst:.3g} kg ({worst_rel:.3g} relative, t = {at:g} s): {'ok' if good else 'FAILED'}")
    print(f"final: mass {float(last['mass']):.6g} kg = {m0:.6g} + {float(last['mass_in']):.6g} - "
          f"{float(last['mass_out']):.6g}")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
