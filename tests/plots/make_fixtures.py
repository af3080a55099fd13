#!/usr/bin/env python3
"""Write the fake analysis tables of tests/plots/fixtures/analysis/ (docs/plots.md format).

Usage: python3 tests/plots/make_fixtures.py [DIR]   (default: the fixtures folder beside it)

One small table of every kind scripts/plot_analysis.py knows (floor_pressure, force_directions,
force_magnitudes, coordination, repose_profile, roughness_spectrum, packing, stress, janssen,
strain) with smooth made-up physics-like data and a fixed random seed. The committed files are
its output; rerun it after changing the format.
"""
import math
import os
import random
import sys


def write(folder, name, notes, columns, rows):
    """columns: ["name [unit]", ...]; rows: lists of floats (nan written "nan")."""
    with open(os.path.join(folder, name + ".csv"), "w") as f:
        for n in notes:
            f.write(f"# {n}\n")
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write(",".join("nan" if math.isnan(v) else f"{v:.6g}" for v in r) + "\n")


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    folder = argv[1] if len(argv) > 1 else os.path.join(here, "fixtures", "analysis")
    os.makedirs(folder, exist_ok=True)
    rng = random.Random(7)
    d, rho_g_h = 0.004, 1226.0
    rows = []
    for k in range(40):
        x = -0.1 + 0.2 * (k + 0.5) / 40
        shape = math.exp(-(x / 0.06) ** 2) * (1 - 0.35 * math.exp(-(x / 0.02) ** 2))
        p = rho_g_h * shape * (1 + 0.25 * rng.gauss(0, 1))
        avg = rho_g_h * shape
        rows.append([x, p, avg, float(rng.randint(0, 6)), x / d, p / rho_g_h, avg / rho_g_h])
    write(folder, "floor_pressure",
          ["rho g h = 1226 Pa", "d = 0.004 m", "total = 98.1 N/m",
           "warning: 3 bins had no contacts"],
          ["x [m]", "p [Pa]", "p_avg [Pa]", "contacts [1]", "x/d [1]", "p/(rho g h) [1]",
           "p_avg/(rho g h) [1]"], rows)
    rows = []
    for k in range(18):
        a = math.pi * (k + 0.5) / 18
        theory = (1 + 0.4 * math.cos(2 * (a - math.pi / 2))) / math.pi
        rows.append([a, theory * (1 + 0.1 * rng.gauss(0, 1)), theory])
    write(folder, "force_directions", ["a2 = 0.4", "contacts = 2412"],
          ["alpha [rad]", "P [1/rad]", "P_theory [1/rad]"], rows)
    rows = []
    for k in range(30):
        f = 5.0 * (k + 0.5) / 30
        theory = math.exp(-f)
        rows.append([f, theory * (1 + 0.15 * rng.gauss(0, 1)), theory])
    write(folder, "force_magnitudes", ["<F> = 0.0132 N"],
          ["F/<F> [1]", "P [1]", "P_theory [1]"], rows)
    probs = [0.01, 0.04, 0.12, 0.30, 0.33, 0.15, 0.04, 0.01]
    write(folder, "coordination", ["Z = 3.61"], ["K [1]", "P [1]"],
          [[float(k), p] for k, p in enumerate(probs)])
    rows = []
    tan_l, tan_r = math.tan(math.radians(28.5)), math.tan(math.radians(29.1))
    for k in range(60):
        x = -0.15 + 0.3 * k / 59
        h = max(0.0, 0.07 - (tan_l * -x if x < 0 else tan_r * x)) + 0.002 * rng.random()
        fl = 0.07 + tan_l * x if -0.11 < x < -0.02 else math.nan
        fr = 0.07 - tan_r * x if 0.02 < x < 0.11 else math.nan
        rows.append([x, h, fl, fr])
    write(folder, "repose_profile", ["angle_left = 28.5 deg", "angle_right = 29.1 deg"],
          ["x [m]", "h [m]", "fit_left [m]", "fit_right [m]"], rows)
    rows = []
    for k in range(40):
        q = 10 ** (1 + 2.5 * k / 39)
        theory = 1e-6 * q ** -2
        rows.append([q, theory * math.exp(0.5 * rng.gauss(0, 1)), theory])
    write(folder, "roughness_spectrum", ["exponent = -2.02"],
          ["k [1/m]", "P [m^3]", "P_theory [m^3]"], rows)
    rows = []
    for j in range(12):
        for i in range(20):
            x, z = -0.095 + 0.01 * i, 0.0025 + 0.005 * j
            top = 0.07 - 0.55 * abs(x)
            rho = 0.82 + 0.02 * rng.gauss(0, 1) - 0.4 * z if z < top else math.nan
            rows.append([x, z, rho])
    write(folder, "packing", ["rho_rel_mean = 0.81"], ["x [m]", "z [m]", "rho_rel [1]"], rows)
    rows = []
    for j in range(24):
        for i in range(10):
            x, z = 0.01 + 0.02 * i, 0.01 + 0.02 * j
            depth = 0.48 - z
            szz = 900 * (1 - math.exp(-depth / 0.12)) + 50 * rng.random()
            sxx = 0.6 * szz
            sxz = 250 * (x - 0.1) / 0.1 * (1 - math.exp(-depth / 0.12))
            mean, rad = (sxx + szz) / 2, math.hypot((szz - sxx) / 2, sxz)
            psi = 0.5 * math.degrees(math.atan2(2 * sxz, sxx - szz))
            rows.append([x, z, sxx, szz, sxz, mean + rad, mean - rad, psi])
    write(folder, "stress", ["bin = 0.02 m"],
          ["x [m]", "z [m]", "sigma_xx [Pa]", "sigma_zz [Pa]", "sigma_xz [Pa]",
           "sigma_major [Pa]", "sigma_minor [Pa]", "psi_deg [deg]"], rows)
    rows = []
    for k in range(25):
        z = 0.02 * k
        szz = 980 * 0.12 * (1 - math.exp(-z / 0.12)) / 0.12
        rows.append([z, 0.64 * szz * (1 + 0.05 * rng.gauss(0, 1)),
                     szz * (1 + 0.05 * rng.gauss(0, 1)), 0.64 * szz, szz])
    write(folder, "janssen", ["K = 0.64", "lambda = 0.12 m", "warning: top 2 bins partly empty"],
          ["z [m]", "sigma_xx [Pa]", "sigma_zz [Pa]", "sigma_xx_theory [Pa]",
           "sigma_zz_theory [Pa]"], rows)
    rows = []
    for j in range(10):
        for i in range(16):
            x, z = 0.005 + 0.01 * i, 0.005 + 0.01 * j
            rows.append([x, z, -0.002 * math.sin(math.pi * x / 0.16) * z / 0.1,
                         0.001 * math.cos(math.pi * x / 0.08) * (1 - z / 0.1)])
    write(folder, "strain", [], ["x [m]", "z [m]", "eps_xx [1]", "eps_xz [1]"], rows)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
