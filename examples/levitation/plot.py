#!/usr/bin/python3
"""Plot the height y(t) and the vertical speed v_y(t) of the levitating ball (cfddem T6).

    /usr/bin/python3 examples/levitation/plot.py OUT [--radius R] [--id ID] [--png FILE]

OUT is the folder of examples/levitation/run.sh (default out/levitation). Reads
  OUT/granulab/CSV/r_y.csv, OUT/granulab/CSV/v_y.csv  (output.particle_series = true, long
      format: header `time,id,r_y`, one row per particle per output time) [m], [m/s]; the rows
      of the ball's id (--id, default the only id present);
  OUT/case/postProcessing/centreline/0/U  (OpenFOAM probes on the centreline x = 3 m at
      y = 1.5, 3, 4.5 m) for the air speed u_f at the ball's height; if it is missing, the
      seed's 3.592 m/s;
  OUT/granulab/final.csv: column `radius` for R, unless --radius is given (default 0.02 m), and
      `fluid_uy`, the air speed at the ball at the end of the run (drawn as a marker).
Writes OUT/levitation.png (or --png FILE) and prints the final height and speed.
For all nine time series of the ball (r_x ... alpha) see scripts/plot_particle_series.py.

The analytic levitation speed (cfddem Eq. 5.4) is v = sqrt(8/3 R g (rho_p - rho_f)/(rho_f c_w)),
3.4993 m/s for R = 0.02 m. In air rising at u_f a ball's terminal velocity is u_f - v: the
horizontal line in the v_y plot; the marker at the end is u_f - v with u_f the air speed at the
ball itself (final.csv). The dotted line -v (drawn when the ball falls faster than v/2) is the
terminal fall speed in still air.
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

# The reader of granulab's CSV/ series lives with scripts/plot_particle_series.py.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import plot_particle_series as particle_series  # noqa: E402

RHO_P = 15.0  # [kg/m^3] polystyrene (ball.toml)
RHO_F = 1.25  # [kg/m^3] air (ball.toml [fluid])
CW = 0.47  # [-] drag coefficient (ball.toml [fluid])
G = 9.81  # [m/s^2]
SEED_FLOW = 3.592  # [m/s] the seed's centreline maximum, when no probe file is found


def levitation_speed(radius):
    """cfddem Eq. 5.4 [m/s]."""
    return math.sqrt(8.0 / 3.0 * radius * G * (RHO_P - RHO_F) / (RHO_F * CW))


def read_long(path, quantity):
    """A long-format particle series file `time,id,<quantity>`: {id: (time, values)}."""
    if not os.path.isfile(path):
        sys.exit(f"plot.py: {path} not found: run granulab with output.particle_series = true "
                 f"(ball.toml sets it)")
    try:
        return particle_series.read_long(path, quantity, np)
    except particle_series.InputError as e:
        sys.exit(f"plot.py: {e}")


def pick(series, path, wanted):
    """The (time, values) of particle `wanted`, or of the only particle present."""
    if wanted is None:
        if len(series) != 1:
            sys.exit(f"plot.py: {path} holds particles {sorted(series)}; choose one with --id")
        wanted = next(iter(series))
    if wanted not in series:
        sys.exit(f"plot.py: no particle id {wanted} in {path} (ids: {sorted(series)})")
    return wanted, series[wanted]


def read_final(out, ball):
    """The ball's row of final.csv as a dict (strings), or None."""
    final = os.path.join(out, "granulab", "final.csv")
    if not os.path.isfile(final):
        return None
    with open(final, newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        if row.get("id", "").strip() == str(ball):
            return row
    return rows[0] if len(rows) == 1 else None


def read_radius(final, given):
    if given is not None:
        return given, "--radius"
    if final is not None and final.get("radius"):
        return float(final["radius"]), "final.csv"
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
    ap.add_argument("--id", type=int, default=None,
                    help="the ball's particle id (default: the only id in CSV/)")
    ap.add_argument("--png", default=None, help="output picture (default OUT/levitation.png)")
    a = ap.parse_args()

    ry_path = os.path.join(a.out, "granulab", "CSV", "r_y.csv")
    vy_path = os.path.join(a.out, "granulab", "CSV", "v_y.csv")
    ball, (t, y) = pick(read_long(ry_path, "r_y"), ry_path, a.id)
    _, (tv, vy) = pick(read_long(vy_path, "v_y"), vy_path, ball)
    final = read_final(a.out, ball)
    radius, rsrc = read_radius(final, a.radius)
    u_ball = None  # air speed u_fy at the ball at the end of the run (final.csv)
    if final is not None and final.get("fluid_uy", "").strip():
        u_ball = float(final["fluid_uy"])
    v_lev = levitation_speed(radius)
    probe = read_probe(a.out)
    if probe is not None:
        u_flow, flow_src = float(probe[1][-1]), f"OpenFOAM centreline at y = 3 m, t = {probe[0][-1]:g} s"
    else:
        u_flow, flow_src = SEED_FLOW, "the seed's centreline maximum"
    v_rise = u_flow - v_lev

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    ax1.plot(t, y, color="C0", label=f"ball centre (particle id {ball})")
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
    if u_ball is not None:
        ax2.plot([tv[-1]], [u_ball - v_lev], "D", color="C4", ms=7, mec="k", mew=0.6, zorder=5,
                 label=f"$u_{{f,ball}} - v$: air at the ball {u_ball:.3f} m/s at "
                       f"t = {tv[-1]:g} s (y = {y[-1]:.2f} m)")
    ax2.set_xlabel("time t [s]")
    ax2.set_ylabel("vertical speed $v_y$ [m/s]")
    ax2.legend(loc="lower right", fontsize=8)
    ax2.grid(alpha=0.3)
    # the interesting part is near zero: the fall at the start reaches about -1 m/s
    lo = min(float(np.min(vy)), -v_lev * 0.1)
    top = max(float(np.max(vy)), v_rise, u_ball - v_lev if u_ball is not None else v_rise)
    ax2.set_ylim(max(lo, -v_lev * 1.1) - 0.05, top + 0.1)

    fig.tight_layout()
    png = a.png or os.path.join(a.out, "levitation.png")
    fig.savefig(png, dpi=120)
    print(f"R = {radius:g} m ({rsrc}), levitation speed v = {v_lev:.4f} m/s; "
          f"air u_f = {u_flow:.4f} m/s ({flow_src}); expected rise u_f - v = {v_rise:+.4f} m/s")
    print(f"at t = {t[-1]:g} s: y = {y[-1]:.4f} m (start {y[0]:g}), v_y = {vy[-1]:+.4f} m/s; "
          f"lowest y = {np.min(y):.4f} m at t = {t[int(np.argmin(y))]:g} s")
    if u_ball is not None:
        print(f"air at the ball at the end (final.csv): u_fy = {u_ball:.4f} m/s, "
              f"u_fy - v = {u_ball - v_lev:+.4f} m/s")
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
