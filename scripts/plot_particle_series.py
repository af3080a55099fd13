#!/usr/bin/env python3
"""Plot the per-particle time series of a granulab run (RUN/CSV/*.csv) as one 3x3 PNG figure.

Usage:
  python3 scripts/plot_particle_series.py RUN [--ids 0,3,5] [--out FILE]

The cfddem seed's nine time-history diagrams (cfddem spec 6.6 and 6.8, thesis Fig. 4.3), one line
per particle id:

  r_x [m]          r_y [m]          phi [rad]
  v_x [m/s]        v_y [m/s]        omega [rad/s]
  a_x [m/s^2]      a_y [m/s^2]      alpha [rad/s^2]

Reads RUN/CSV/r_x.csv, r_y.csv, phi.csv, v_x.csv, v_y.csv, omega.csv, a_x.csv, a_y.csv and
alpha.csv, which granulab writes with `[output] particle_series = true` (every
output.series_interval): long format, header `time,id,<quantity>` (e.g. `time,id,r_y`), one row
per particle per output time; a particle that enters through an inlet or leaves through an
outlet has rows only while it is in the domain. RUN/summary.json, if present, names the scene
in the title. A missing file leaves its panel empty (with a note); a cut last row (a run still
writing) is ignored.

--ids chooses the particles (comma-separated ids); default: all when there are at most 20,
otherwise the 20 smallest ids (a note says so). Writes RUN/particle_series.png, or FILE with --out.
Exit status: 0 written, 2 missing or malformed input (no CSV/ folder: run with
output.particle_series = true), 3 matplotlib or numpy missing.
"""
import argparse
import json
import os
import sys

EXIT_OK = 0
EXIT_INPUT = 2
EXIT_DEPENDENCY = 3
MAX_DEFAULT_IDS = 20

# (file stem, axis label, unit), row by row: positions, velocities, accelerations
QUANTITIES = [
    ("r_x", "position $r_x$", "m"), ("r_y", "position $r_y$", "m"),
    ("phi", "rotation angle $\\varphi$", "rad"),
    ("v_x", "velocity $v_x$", "m/s"), ("v_y", "velocity $v_y$", "m/s"),
    ("omega", "angular velocity $\\omega$", "rad/s"),
    ("a_x", "acceleration $a_x$", "m/s²"), ("a_y", "acceleration $a_y$", "m/s²"),
    ("alpha", "angular acceleration $\\alpha$", "rad/s²"),
]


class InputError(Exception):
    """A missing or malformed input file; the message names the file."""


def import_plotting():
    """numpy and matplotlib (Agg backend), or exit 3 with the Debian packages to install."""
    try:
        import numpy
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as pyplot
    except ImportError as e:
        print(f"plot_particle_series: {e}; install python3-matplotlib and python3-numpy "
              "(scripts/setup.sh does)", file=sys.stderr)
        sys.exit(EXIT_DEPENDENCY)
    return numpy, pyplot


def read_long(path, quantity, np, allow_empty=False):
    """A long-format file `time,id,<quantity>`: {id: (time array, value array)}, rows by time.
    Raises InputError for a malformed file, or one without data rows unless `allow_empty`.
    The one reader of granulab's CSV/ series (examples/levitation/plot.py and
    examples/channel/plot_trajectories.py import it)."""
    with open(path) as f:
        lines = [ln for ln in f.read().split("\n")]
    while lines and not lines[-1].strip():
        lines.pop()
    if not lines:
        raise InputError(f"{path}: empty file, expected the header time,id,{quantity}")
    header = [h.strip() for h in lines[0].split(",")]
    if header != ["time", "id", quantity]:
        raise InputError(f"{path}:1: header {','.join(header)}, expected time,id,{quantity}")
    times, ids, values = [], [], []
    for k, line in enumerate(lines[1:], start=2):
        cells = line.split(",")
        if len(cells) != 3:
            if k == len(lines):  # a run still writing, or killed mid-line
                print(f"plot_particle_series: {path}:{k}: incomplete last row ignored",
                      file=sys.stderr)
                break
            raise InputError(f"{path}:{k}: {len(cells)} cells, expected 3 (time,id,{quantity})")
        try:
            t, i, v = float(cells[0]), int(cells[1]), float(cells[2])
        except ValueError:
            raise InputError(f"{path}:{k}: '{line.strip()}' is not time,integer id,number")
        times.append(t)
        ids.append(i)
        values.append(v)
    if not times:
        if allow_empty:
            return {}
        raise InputError(f"{path}: no data rows after the header")
    times, ids, values = np.array(times), np.array(ids), np.array(values)
    out = {}
    order = np.argsort(ids, kind="stable")  # rows of one id keep their (time) order
    ids_sorted = ids[order]
    starts = np.flatnonzero(np.r_[True, ids_sorted[1:] != ids_sorted[:-1]])
    for s, e in zip(starts, np.r_[starts[1:], len(order)]):
        rows = order[s:e]
        rows = rows[np.argsort(times[rows], kind="stable")]
        out[int(ids_sorted[s])] = (times[rows], values[rows])
    return out


def parse_ids(text):
    try:
        ids = [int(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected comma-separated particle ids, e.g. 0,3,5; "
                                         f"got '{text}'")
    if not ids:
        raise argparse.ArgumentTypeError("no particle id given")
    return ids


def parse_args(argv):
    p = argparse.ArgumentParser(
        description="Plot RUN/CSV/*.csv (output.particle_series = true) of a granulab run: "
                    "the nine time histories r_x, r_y, phi, v_x, v_y, omega, a_x, a_y, alpha "
                    "of chosen particles in one 3x3 figure.",
        epilog="example: python3 scripts/plot_particle_series.py out/levitation/granulab")
    p.add_argument("run", help="output folder of `granulab run` (holds CSV/)")
    p.add_argument("--ids", type=parse_ids, metavar="I,J,...",
                   help=f"particle ids to draw (default: all if at most {MAX_DEFAULT_IDS}, "
                        f"else the first {MAX_DEFAULT_IDS})")
    p.add_argument("--out", metavar="FILE",
                   help="output picture (default RUN/particle_series.png)")
    return p.parse_args(argv)


def scene_name(run):
    path = os.path.join(run, "summary.json")
    try:
        with open(path) as f:
            summary = json.load(f)
        scene = os.path.basename(str(summary.get("scene", "")))
    except (OSError, ValueError, AttributeError):
        scene = ""
    return scene or os.path.basename(os.path.normpath(run))


def id_text(ids):
    """'0, 3, 5' or '0-19' for a contiguous range."""
    if len(ids) > 3 and ids == list(range(ids[0], ids[-1] + 1)):
        return f"{ids[0]}-{ids[-1]}"
    return ", ".join(str(i) for i in ids)


def main(argv=None):
    args = parse_args(argv)
    np, plt = import_plotting()
    folder = os.path.join(args.run, "CSV")
    if not os.path.isdir(folder):
        what = "no such folder" if os.path.isdir(args.run) else "no such run folder"
        print(f"plot_particle_series: {folder}: {what}; run with output.particle_series = true "
              f"(in the scene's [output] section, or --set output.particle_series=true)",
              file=sys.stderr)
        return EXIT_INPUT
    series, missing = {}, []
    try:
        for stem, _, _ in QUANTITIES:
            path = os.path.join(folder, stem + ".csv")
            if os.path.isfile(path):
                series[stem] = read_long(path, stem, np)
            else:
                missing.append(stem)
    except InputError as e:
        print(f"plot_particle_series: {e}", file=sys.stderr)
        return EXIT_INPUT
    if not series:
        print(f"plot_particle_series: {folder}: none of the files "
              f"{', '.join(s + '.csv' for s, _, _ in QUANTITIES)}; run with "
              f"output.particle_series = true", file=sys.stderr)
        return EXIT_INPUT
    for stem in missing:
        print(f"plot_particle_series: {folder}/{stem}.csv missing; its panel stays empty",
              file=sys.stderr)

    present = sorted(set().union(*(s.keys() for s in series.values())))
    note = ""
    if args.ids is not None:
        unknown = [i for i in args.ids if i not in present]
        if unknown:
            shown = id_text(present) if len(present) <= 30 else \
                f"{', '.join(map(str, present[:30]))}, ... ({len(present)} in all)"
            print(f"plot_particle_series: no particle id {', '.join(map(str, unknown))} in "
                  f"{folder}; ids present: {shown}", file=sys.stderr)
            return EXIT_INPUT
        ids = list(dict.fromkeys(args.ids))
    elif len(present) <= MAX_DEFAULT_IDS:
        ids = present
    else:
        ids = present[:MAX_DEFAULT_IDS]
        note = f"the first {MAX_DEFAULT_IDS} of {len(present)} particles (--ids to choose)"
        print(f"plot_particle_series: {len(present)} particles; drawing {note}", file=sys.stderr)

    plt.rcParams.update({"font.size": 10, "axes.titlesize": 11, "legend.fontsize": 8})
    fig, axes = plt.subplots(3, 3, sharex=True, figsize=(13, 9.5), layout="constrained")
    cmap = plt.get_cmap("tab10" if len(ids) <= 10 else "tab20")
    colors = {i: cmap(k % cmap.N) for k, i in enumerate(ids)}
    lw = 1.4 if len(ids) <= 5 else 1.0
    for ax, (stem, label, unit) in zip(axes.flat, QUANTITIES):
        ax.set_ylabel(f"{label} [{unit}]")
        ax.grid(True, alpha=0.3)
        data = series.get(stem)
        if data is None:
            ax.text(0.5, 0.5, f"no CSV/{stem}.csv", transform=ax.transAxes, ha="center",
                    va="center", color="0.4")
            continue
        for i in ids:
            if i not in data:
                continue
            t, v = data[i]
            marker = "." if len(t) == 1 else None  # a particle seen at one output time only
            ax.plot(t, v, color=colors[i], lw=lw, marker=marker, label=f"id {i}")
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 4), useOffset=False)
    for ax in axes[-1]:
        ax.set_xlabel("time t [s]")
    if len(ids) <= 10:
        handles, labels = axes[0, 0].get_legend_handles_labels()
        if handles:  # beside the top right panel (constrained layout makes room for it)
            axes[0, 2].legend(handles, labels, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                              title="particle", borderaxespad=0)
    t_all = np.concatenate([s[i][0] for s in series.values() for i in ids if i in s])
    t_text = f"t = {t_all.min():g} ... {t_all.max():g} s" if len(t_all) else "no rows"
    sub = f"particle{'s' if len(ids) != 1 else ''} {id_text(ids)}"
    if note:
        sub = note + f": ids {id_text(ids)}"
    fig.suptitle(f"Particle time series: {scene_name(args.run)}\n{sub}, {t_text}",
                 fontsize="medium")
    out = args.out or os.path.join(args.run, "particle_series.png")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(out)
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
