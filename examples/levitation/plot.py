#!/usr/bin/python3
"""Plot the height y(t) and the vertical speed v_y(t) of the levitating ball (cfddem T6).

    /usr/bin/python3 examples/levitation/plot.py OUT [--radius R] [--png FILE]

OUT is the folder of examples/levitation/run.sh (default out/levitation). Reads
  OUT/granulab/CSV/r_y.csv, OUT/granulab/CSV/v_y.csv  (output.particle_series = true: a column
      `time` [s], then one column per particle id, header `time,0`) [m], [m/s];
  OUT/case/postProcessing/centreline/0/U  (OpenFOAM probes on the centreline x = 3 m at
      y = 1.5, 3, 4.5 m) for the air speed u_f at the ball's height; if it is missing, the
      seed's 3.592 m/s;
  OUT/granulab/final.csv (column `radius`) for R, unless --radius is given (default 0.02 m).
Without CSV/ (a granulab that does not write particle series yet), y(t) comes from series.csv's
potential energy m g y (one ball) and v_y(t) from its differences.
Writes OUT/levitation.png (or --png FILE) and prints the final height and speed.

The analytic levitation speed (cfddem Eq. 5.4) is v = sqrt(8/3 R g (rho_p - rho_f)/(rho_f c_w)),
3.4993 m/s for R = 0.02 m. In air rising at u_f a ball's terminal velocity is u_f - v: the
horizontal line in the v_y plot. The dotted line -v (drawn when the ball falls faster than v/2)
is the terminal fall speed in still air.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RHO_P = 15.0  # [kg/m^3] polystyrene (ball.toml)
RHO_F = 1.25  # [kg/m^3] air (ball.toml [fluid])
CW = 0.47  # [-] drag coefficient (ball.toml [fluid])
G = 9.81  # [m/s^2]
SEED_FLOW = 3.592  # [m/s] the seed's centreline maximum, when no probe file is found


def levitation_speed(radius):
    """cfddem Eq. 5.4 [m/s]."""
    return math.sqrt(8.0 / 3.0 * radius * G * (RHO_P - RHO_F) / (RHO_F * CW))


def read_series(path):
    """A per-particle series file: returns (time, values of the first particle column)."""
    if not os.path.isfile(path):
        return None
    with open(path, newline="") as f:
        header = next(csv.reader(f))
    header = [h.strip() for h in header]
    if "time" not in header:
        sys.exit(f"plot.py: {path}: no column 'time' in the header {header}")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    it = header.index("time")
    ip = header.index("0") if "0" in header else next(i for i in range(len(header)) if i != it)
    return data[:, it], data[:, ip]


def series_fallback(out):
    """Without CSV/: y from series.csv's potential energy m g y of the single ball (mass from
    final.csv), v_y = dy/dt by differences. Returns (t, y, v_y) or exits."""
    series = os.path.join(out, "granulab", "series.csv")
    final = os.path.join(out, "granulab", "final.csv")
    if not (os.path.isfile(series) and os.path.isfile(final)):
        sys.exit(f"plot.py: {out}/granulab/CSV/r_y.csv not found (needs output.particle_series = "
                 f"true in ball.toml), nor series.csv and final.csv")
    with open(final, newline="") as f:
        rows = list(csv.DictReader(f))
    with open(series, newline="") as f:
        header = [h.strip() for h in next(csv.reader(f))]
    if len(rows) != 1 or "potential_energy" not in header:
        sys.exit(f"plot.py: {out}/granulab/CSV/r_y.csv not found, and series.csv cannot replace it")
    data = np.loadtxt(series, delimiter=",", skiprows=1, ndmin=2)
    t = data[:, header.index("time")]
    y = data[:, header.index("potential_energy")] / (float(rows[0]["mass"]) * G)
    print("plot.py: no CSV/r_y.csv (output.particle_series); y from series.csv's potential "
          "energy, v_y = dy/dt")
    return t, y, np.gradient(y, t)


def read_radius(out, given):
    if given is not None:
        return given, "--radius"
    final = os.path.join(out, "granulab", "final.csv")
    if os.path.isfile(final):
        with open(final, newline="") as f:
            rows = list(csv.DictReader(f))
        if rows and "radius" in rows[0]:
            return float(rows[0]["radius"]), "final.csv"
    return 0.02, "default"


def read_probe(out):
    """Centreline air speed u_y [m/s] at (3, 3) over time from the OpenFOAM probes, or None."""
    path = os.path.join(out, "case", "postProcessing", "centreline", "0", "U")
    if not os.path.isfile(path):
        return None
    t, u = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            tok = line.replace("(", " ").replace(")", " ").split()
            if len(tok) >= 7:  # time, then (ux uy uz) per probe; probe 1 is y = 3 m
                t.append(float(tok[0]))
                u.append(float(tok[5]))
    return (np.array(t), np.array(u)) if t else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", nargs="?", default="out/levitation", help="run.sh output folder")
    ap.add_argument("--radius", type=float, default=None, help="ball radius [m]")
    ap.add_argument("--png", default=None, help="output picture (default OUT/levitation.png)")
    a = ap.parse_args()

    ry = read_series(os.path.join(a.out, "granulab", "CSV", "r_y.csv"))
    vy_ = read_series(os.path.join(a.out, "granulab", "CSV", "v_y.csv"))
    if ry is not None and vy_ is not None:
        (t, y), (tv, vy) = ry, vy_
    else:
        t, y, vy = series_fallback(a.out)
        tv = t
    radius, rsrc = read_radius(a.out, a.radius)
    v_lev = levitation_speed(radius)
    probe = read_probe(a.out)
    if probe is not None:
        u_flow, flow_src = float(probe[1][-1]), f"OpenFOAM centreline at y = 3 m, t = {probe[0][-1]:g} s"
    else:
        u_flow, flow_src = SEED_FLOW, "the seed's centreline maximum"
    v_rise = u_flow - v_lev

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    ax1.plot(t, y, color="C0", label="ball centre")
    ax1.axhline(y[0], color="0.6", lw=0.8, ls=":", label=f"start, y = {y[0]:g} m")
    ax1.set_ylabel("height y [m]")
    ax1.set_title(f"polystyrene ball, R = {radius:g} m, in air rising at {u_flow:.3f} m/s")
    ax1.legend(loc="best")
    ax1.grid(alpha=0.3)

    ax2.plot(tv, vy, color="C1", label="ball speed $v_y$")
    ax2.axhline(v_rise, color="C2", ls="--",
                label=f"$u_f - v$ = {u_flow:.3f} - {v_lev:.4f} = {v_rise:+.4f} m/s")
    if float(np.min(vy)) < -0.5 * v_lev:  # shown only when the ball falls that fast
        ax2.axhline(-v_lev, color="C3", ls=":", lw=1,
                    label=f"$-v$ = {-v_lev:.4f} m/s (terminal fall in still air)")
    if probe is not None:
        ax2.plot(probe[0], probe[1] - v_lev, color="C2", lw=0.8, alpha=0.6,
                 label="$u_f(t) - v$ (centreline probe at y = 3 m)")
    ax2.set_xlabel("time t [s]")
    ax2.set_ylabel("vertical speed $v_y$ [m/s]")
    ax2.legend(loc="lower right", fontsize=8)
    ax2.grid(alpha=0.3)
    # the interesting part is near zero: the fall at the start reaches about -1 m/s
    lo = min(float(np.min(vy)), -v_lev * 0.1)
    ax2.set_ylim(max(lo, -v_lev * 1.1) - 0.05, max(float(np.max(vy)), v_rise) + 0.1)

    fig.tight_layout()
    png = a.png or os.path.join(a.out, "levitation.png")
    fig.savefig(png, dpi=120)
    print(f"R = {radius:g} m ({rsrc}), levitation speed v = {v_lev:.4f} m/s; "
          f"air u_f = {u_flow:.4f} m/s ({flow_src}); expected rise u_f - v = {v_rise:+.4f} m/s")
    print(f"at t = {t[-1]:g} s: y = {y[-1]:.4f} m (start {y[0]:g}), v_y = {vy[-1]:+.4f} m/s; "
          f"lowest y = {np.min(y):.4f} m at t = {t[int(np.argmin(y))]:g} s")
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
