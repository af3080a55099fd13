#!/usr/bin/env python3
"""Plot the time series of a granulab run (OUTDIR/series.csv) as PNG figures.

Usage:
  python3 scripts/plot_series.py OUTDIR [--out DIR] [--columns a,b,...] [--haff-window t1,t2]

Reads OUTDIR/series.csv (one row per output time, columns described in docs/scene-format.md
and docs/plots.md) and OUTDIR/summary.json (engine, dimension, scene, status, and for edmd the
kinetic-theory thresholds). Writes one PNG per figure (150 dpi) into OUTDIR, or DIR with --out:

  dem runs   series_energies.png   kinetic, rotational, potential, elastic, total energy [J]
             series_contacts.png   contacts, wall contacts, largest overlap / radius, list builds
             series_walls.png      wall_<name>_fx/_fy [N] per wall (and _dx/_dy [m] of moving walls)
             series_machines.png   gravity_x/_y [m/s^2], size_scale (when the scene has them)
             series_flow.png       particles, mass [kg], inserted/removed counts and, per outlet,
                                   the removed mass and its slope, the mass flow [kg/s]
  edmd runs  series_energies.png   energies and the energy dissipated in collisions [J]
             series_temperature.png  T = 2E/D [J], Haff's law T0 / (1 + t/tau)^2, tau fitted
                                   by least squares (dashed, tau in the legend), the engine's
                                   kinetic-theory Haff curve (dotted) and T / T_fit
             series_collisions.png collisions per particle, collision frequency [1/s], mean free
                                   path [m]
             series_pressure.png   pressure [N/m in 2D, Pa in 3D], PV/(NT) - 1, volume fraction
             series_velocity.png   velocity kurtosis (3 for a Gaussian), local volume fraction
                                   quantiles
             series_clusters.png   cluster count and largest cluster, moments M1, M2, q_x
  any run    series_other.png      columns no figure above claims
  --columns  series_columns.png    just those columns, one panel per unit

Haff fit: T(t) = T0 / (1 + t/tau)^2 with T0 the first row's temperature and tau minimising
sum (ln T - ln T_Haff)^2 (rows spaced logarithmically weigh every decade alike). Haff's law
holds in the homogeneous cooling state, so the fit uses the rows with scaled time
tau <= tau_hc (summary.json "theory"), or all rows without it; --haff-window overrides.
Exit status: 0 written, 2 missing or malformed input, 3 matplotlib or numpy missing.
"""
import argparse
import csv
import json
import math
import os
import re
import sys

EXIT_OK = 0
EXIT_INPUT = 2
EXIT_DEPENDENCY = 3


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
        print(f"plot_series: {e}; install python3-matplotlib and python3-numpy "
              "(scripts/setup.sh does)", file=sys.stderr)
        sys.exit(EXIT_DEPENDENCY)
    return numpy, matplotlib, pyplot


def read_series(path, np):
    """Header and columns of series.csv as {name: float array}; a cut last row is dropped."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file (is this the output folder of a granulab run?)")
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    rows = [r for r in rows if r]
    if not rows:
        raise InputError(f"{path}: empty file, expected a header line")
    header = [h.strip() for h in rows[0]]
    if not header or any(not h for h in header) or len(set(header)) != len(header):
        raise InputError(f"{path}:1: malformed header (empty or repeated column names)")
    data = []
    for k, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            if k == len(rows):  # a run still writing, or killed mid-line
                print(f"plot_series: {path}:{k}: incomplete last row ignored", file=sys.stderr)
                break
            raise InputError(f"{path}:{k}: {len(row)} cells, the header has {len(header)}")
        try:
            data.append([float(c) for c in row])
        except ValueError:
            bad = next(c for c in row if not _is_number(c))
            raise InputError(f"{path}:{k}: '{bad}' is not a number")
    if not data:
        raise InputError(f"{path}: no data rows after the header")
    if "time" not in header:
        raise InputError(f"{path}:1: no 'time' column")
    table = np.array(data, dtype=float)
    return header, {name: table[:, j] for j, name in enumerate(header)}


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def read_summary(path, header):
    """summary.json as a dict (engine guessed from the columns when the file is missing)."""
    if not os.path.isfile(path):
        engine = "edmd" if "collisions_per_particle" in header else "dem"
        print(f"plot_series: {path} missing; taking the engine as {engine} from the columns",
              file=sys.stderr)
        return {"engine": engine}
    try:
        with open(path) as f:
            summary = json.load(f)
    except (OSError, ValueError) as e:
        raise InputError(f"{path}: not valid JSON ({e})")
    if not isinstance(summary, dict):
        raise InputError(f"{path}: expected a JSON object")
    return summary


def column_unit(name, engine, dimension):
    """Unit of a series.csv column ("1" for counts and pure numbers); None when unknown."""
    if name == "time":
        return "s"
    if name.endswith("_energy") or name in ("energy_per_particle", "temperature",
                                            "temperature_haff"):
        return "J"
    if re.fullmatch(r"wall_.+_f[xy]", name):
        return "N"
    if re.fullmatch(r"wall_.+_d[xy]", name):
        return "m"
    if name in ("gravity_x", "gravity_y"):
        return "m/s²"
    if name in ("mass", "mass_in", "mass_out") or re.fullmatch(r"outlet_.+_mass", name):
        return "kg"
    if name == "collision_frequency":
        return "1/s"
    if name == "mean_free_path":
        return "m"
    if name == "pressure":
        return "N/m" if dimension == 2 else "Pa"
    known_pure = {"step", "contacts", "wall_contacts", "max_overlap_ratio", "neighbor_builds",
                  "size_scale", "particles", "inserted", "skipped", "removed", "tau", "events",
                  "collisions", "collisions_per_particle", "wall_collisions", "volume_fraction",
                  "reduced_pressure", "tc_elastic_fraction", "kurtosis", "clusters", "M1", "M2",
                  "M1_reduced", "M2_reduced", "largest_cluster", "q_x"}
    if name in known_pure or re.fullmatch(r"kurtosis_[xyz]|nu_q\d\d|outlet_.+_removed", name):
        return "1"
    return None


LABELS = {
    "kinetic_energy": "kinetic", "rotational_energy": "rotational",
    "potential_energy": "potential", "elastic_energy": "elastic", "total_energy": "total",
    "dissipated_energy": "dissipated in collisions", "contacts": "particle-particle",
    "wall_contacts": "particle-wall", "max_overlap_ratio": "largest overlap / radius",
    "neighbor_builds": "neighbour-list builds (cumulative)", "particles": "particles",
    "inserted": "inserted", "skipped": "skipped (no room)", "removed": "removed",
    "mass": "in the domain", "mass_in": "inserted (cumulative)", "mass_out": "removed (cumulative)",
    "collisions_per_particle": "2C/N", "collision_frequency": "f_E = 2 dC/(N dt)",
    "mean_free_path": "l_E = v̄ / f_E", "pressure": "P (collisional virial)",
    "reduced_pressure": "PV/(NT) − 1", "volume_fraction": "volume fraction ν",
    "tc_elastic_fraction": "TC-elastic collisions / all", "kurtosis": "pooled",
    "clusters": "clusters", "largest_cluster": "largest cluster N_x", "q_x": "q_x = N_x / N",
    "M1": "M1", "M2": "M2", "M1_reduced": "M'1", "M2_reduced": "M'2",
    "gravity_x": "g_x", "gravity_y": "g_y", "size_scale": "size scale s(t)",
}


STYLES = {"total_energy": {"color": "k", "linestyle": "--"}}


def label_of(name):
    m = re.fullmatch(r"outlet_(.+)_(mass|removed)", name)
    if m and name not in LABELS:
        return f"outlet {m.group(1)}"
    return LABELS.get(name, name)


def panel(ylabel, unit, columns, logy=False, styles=None, extra=None):
    """One subplot: columns drawn against time; extra(ax) adds curves (fits, derived data)."""
    return {"ylabel": ylabel, "unit": unit, "columns": columns, "logy": logy,
            "styles": styles or {}, "extra": extra}


def figure(stem, title, panels):
    return {"stem": stem, "title": title, "panels": [p for p in panels if p["columns"]
                                                     or p["extra"]]}


def dem_figures(header, data, np):
    """Figures of a dem run's series.csv: energies, contacts, walls, machines, flow."""
    energies = [c for c in header if c.endswith("_energy")]
    big = [c for c in energies if c in ("potential_energy", "total_energy")]
    small = [c for c in energies if c not in big]
    figs = [figure("energies", "Energies", [
        panel("energy", "J", big),
        panel("energy (log scale)", "J", small, logy=True),
    ])]
    figs.append(figure("contacts", "Contacts", [
        panel("contacts", "1", [c for c in ("contacts", "wall_contacts") if c in header]),
        panel("overlap / radius", "1", [c for c in ("max_overlap_ratio",) if c in header]),
        panel("builds", "1", [c for c in ("neighbor_builds",) if c in header]),
    ]))
    walls = []
    for c in header:
        m = re.fullmatch(r"wall_(.+)_fx", c)
        if m and f"wall_{m.group(1)}_fy" in header:
            walls.append(m.group(1))
    colors = {w: f"C{k % 10}" for k, w in enumerate(walls)}
    force_x = {f"wall_{w}_fx": {"color": colors[w], "label": w} for w in walls}
    force_y = {f"wall_{w}_fy": {"color": colors[w], "label": w} for w in walls}
    moved = [w for w in walls if f"wall_{w}_dx" in header]
    disp = {}
    for w in moved:
        disp[f"wall_{w}_dx"] = {"color": colors[w], "label": f"{w} x"}
        disp[f"wall_{w}_dy"] = {"color": colors[w], "label": f"{w} y", "linestyle": "--"}
    def wall_sum(component):
        def draw_sum(ax):
            if len(walls) > 1:
                total = sum(data[f"wall_{w}_f{component}"] for w in walls)
                ax.plot(data["time"], total, "--", color="k", lw=1.4, label="sum of the walls")
        return draw_sum
    figs.append(figure("walls", "Forces on the walls (sum over the wall's contacts)", [
        panel("force F_x", "N", list(force_x), styles=force_x, extra=wall_sum("x")),
        panel("force F_y", "N", list(force_y), styles=force_y, extra=wall_sum("y")),
        panel("displacement", "m", list(disp), styles=disp),
    ]))
    figs.append(figure("machines", "Machines", [
        panel("gravity", "m/s²", [c for c in ("gravity_x", "gravity_y") if c in header]),
        panel("size scale", "1", [c for c in ("size_scale",) if c in header]),
    ]))
    if "particles" in header:
        outlets = [m.group(1) for m in (re.fullmatch(r"outlet_(.+)_mass", c) for c in header) if m]
        masses = [c for c in ("mass", "mass_in", "mass_out") if c in header]
        masses += [f"outlet_{o}_mass" for o in outlets]
        counts = [c for c in ("inserted", "skipped", "removed") if c in header]
        counts += [f"outlet_{o}_removed" for o in outlets if f"outlet_{o}_removed" in header]
        styles = {f"outlet_{o}_mass": {"label": f"outlet {o}", "linestyle": "--"} for o in outlets}
        styles.update({f"outlet_{o}_removed": {"label": f"outlet {o}", "linestyle": "--"}
                       for o in outlets})

        def mass_flow(ax):
            t = data["time"]
            drawn = False
            for k, o in enumerate(outlets):
                m = data[f"outlet_{o}_mass"]
                if len(t) < 2 or not np.any(m > 0):
                    continue
                rate = np.diff(m) / np.diff(t)
                ax.step(t[1:], rate, where="pre", color=f"C{k}", lw=1.2,
                        label=f"outlet {o}: row-to-row slope")
                flowing = np.nonzero(m > 0)[0]
                start = max(0, flowing[0] - 1)
                if len(t) - start >= 3:
                    slope = np.polyfit(t[start:], m[start:], 1)[0]
                    ax.plot(t[start:], np.full(len(t) - start, slope), "--", color=f"C{k}",
                            lw=2, label=f"outlet {o}: mean {slope:.4g} kg/s "
                                        f"(fit from t = {t[start]:.3g} s)")
                drawn = True
            if not drawn:
                ax.text(0.5, 0.5, "no mass left through an outlet", transform=ax.transAxes,
                        ha="center", va="center", color="0.4")
        figs.append(figure("flow", "Particles in and out", [
            panel("particles", "1", ["particles"]),
            panel("mass", "kg", masses, styles=styles),
            panel("particles (cumulative)", "1", counts, styles=styles),
            panel("mass flow", "kg/s", [],
                  extra=mass_flow if outlets else None),
        ]))
    return figs


def log_spaced(t, np):
    """True when the rows' times grow geometrically (edmd series = "log")."""
    pos = t[t > 0]
    if len(pos) < 5 or pos[-1] / pos[0] < 100:
        return False
    steps = np.diff(np.log(pos))
    return bool(np.all(steps > 0) and np.std(steps) < 0.25 * np.mean(steps))


def fit_haff(t, temp, window, np):
    """tau of T0 / (1 + t/tau)^2 minimising sum (ln T - ln fit)^2 over the rows in window.

    T0 is the temperature of the first row (t = 0). Returns (tau, T0, rows used), or None when
    the gas does not cool or too few rows lie in the window."""
    ok = np.isfinite(temp) & (temp > 0)
    if not ok[0] or t[0] != 0:
        return None
    temp0 = temp[0]
    sel = ok & (t > 0) & (t >= window[0]) & (t <= window[1])
    if np.count_nonzero(sel) < 3 or np.min(temp[sel]) > 0.95 * temp0:
        return None
    ts, lnr = t[sel], np.log(temp[sel] / temp0)

    def cost(log_tau):
        return float(np.sum((lnr + 2 * np.log1p(ts / math.exp(log_tau))) ** 2))

    lo, hi = math.log(ts.min()) - 5, math.log(ts.max()) + 5
    grid = np.linspace(lo, hi, 401)
    k = int(np.argmin([cost(g) for g in grid]))
    if k == 0 or k == len(grid) - 1:
        return None
    a, b = grid[k - 1], grid[k + 1]
    golden = (math.sqrt(5) - 1) / 2
    for _ in range(80):  # golden-section refinement of the bracketing grid interval
        c, d = b - golden * (b - a), a + golden * (b - a)
        if cost(c) < cost(d):
            b = d
        else:
            a = c
    return math.exp((a + b) / 2), temp0, int(np.count_nonzero(sel))


def haff_window(args_window, summary, data):
    """(t1, t2) of the Haff fit and a description for the legend."""
    if args_window is not None:
        return args_window, f"{args_window[0]:g} s ≤ t ≤ {args_window[1]:g} s"
    tau_hc = summary.get("theory", {}).get("tau_hc") if isinstance(summary.get("theory"),
                                                                    dict) else None
    if tau_hc and "tau" in data and data["tau"][-1] > tau_hc:
        inside = data["time"][data["tau"] <= tau_hc]
        return (0.0, float(inside.max())), f"τ ≤ τ_hc = {tau_hc:.3g}"
    return (0.0, math.inf), "all rows"


def edmd_figures(header, data, summary, args, np):
    """Figures of an edmd run's series.csv: energies, temperature with Haff fit, collisions,
    pressure, velocity statistics, clusters."""
    energies = [c for c in header if c.endswith("_energy")]
    figs = [figure("energies", "Energies", [panel("energy", "J", energies, logy=True)])]
    t = data["time"]
    if "temperature" in header:
        window, window_text = haff_window(args.haff_window, summary, data)
        fit = fit_haff(t, data["temperature"], window, np)

        def temperature_theory(ax):
            if "temperature_haff" in header and np.any(data["temperature_haff"] != data[
                    "temperature_haff"][0]):
                ax.plot(t, data["temperature_haff"], ":", color="0.3", lw=1.6,
                        label="Haff, kinetic theory (engine)")
            if fit:
                tau, temp0, used = fit
                ax.plot(t, temp0 / (1 + t / tau) ** 2, "--", color="C3", lw=1.8,
                        label=f"Haff fit T0/(1 + t/τ)², τ = {tau:.4g} s ({window_text})")
                if math.isfinite(window[1]) and window[1] < t.max():
                    ax.axvline(window[1], color="C3", lw=0.8, alpha=0.6,
                               label="end of the fit rows")

        def temperature_ratio(ax):
            tau, temp0, _ = fit
            ax.plot(t, data["temperature"] / (temp0 / (1 + t / tau) ** 2), color="C0",
                    label="T / T_Haff fit")
            ax.axhline(1, color="C3", ls="--", lw=1)
        figs.append(figure("temperature", "Granular temperature and Haff's law", [
            panel("temperature T = 2E/D", "J", ["temperature"], logy=True,
                  styles={"temperature": {"label": "T (measured)", "lw": 2.2}},
                  extra=temperature_theory),
            panel("T / T_Haff fit", "1", [], logy=True,
                  extra=temperature_ratio if fit else None),
        ]))
        if fit is None:
            print("plot_series: no Haff fit (the gas does not cool, or fewer than 3 rows in "
                  "the fit window)", file=sys.stderr)
    figs.append(figure("collisions", "Collisions", [
        panel("collisions per particle", "1",
              [c for c in ("collisions_per_particle",) if c in header]),
        panel("collision frequency", "1/s", [c for c in ("collision_frequency",) if c in header],
              logy=True),
        panel("mean free path", "m", [c for c in ("mean_free_path",) if c in header]),
    ]))
    figs.append(figure("pressure", "Pressure and density", [
        panel("pressure", column_unit("pressure", "edmd", summary.get("dimension")),
              [c for c in ("pressure",) if c in header], logy=True),
        panel("reduced pressure", "1", [c for c in ("reduced_pressure",) if c in header]),
        panel("fraction", "1", [c for c in ("volume_fraction", "tc_elastic_fraction")
                                if c in header]),
    ]))
    kurt = [c for c in header if c == "kurtosis" or re.fullmatch(r"kurtosis_[xyz]", c)]
    quantiles = [c for c in header if re.fullmatch(r"nu_q\d\d", c)]

    def gaussian(ax):
        ax.axhline(3, color="0.3", ls=":", lw=1.2, label="Gaussian (3)")
    qstyles = {c: {"label": f"{int(c[-2:])} %", "color": _ramp(k, len(quantiles))}
               for k, c in enumerate(quantiles)}
    figs.append(figure("velocity", "Velocity distribution and local density", [
        panel("velocity kurtosis", "1", kurt, extra=gaussian if kurt else None),
        panel("local volume fraction quantiles", "1", quantiles, styles=qstyles),
    ]))
    figs.append(figure("clusters", "Clusters (surface gap below δ)", [
        panel("count", "1", [c for c in ("clusters", "largest_cluster") if c in header],
              logy=True),
        panel("moments", "1", [c for c in ("M1", "M2", "M1_reduced", "M2_reduced")
                               if c in header], logy=True),
        panel("q_x", "1", [c for c in ("q_x",) if c in header]),
    ]))
    return figs


def _ramp(k, n):
    """Colour k of n along a sequential colour map (for ordered quantiles)."""
    import matplotlib
    return matplotlib.colormaps["viridis"](0.1 + 0.8 * k / max(1, n - 1))


def other_figure(header, data, figs, engine, dimension, np):
    """The columns no figure shows (except time and counters), one panel per unit."""
    shown = {c for f in figs for p in f["panels"] for c in p["columns"]}
    skip = {"time", "step", "tau", "events", "collisions", "wall_collisions",
            "temperature_haff", "energy_per_particle"}
    rest = [c for c in header if c not in shown and c not in skip
            and np.any(np.nan_to_num(data[c]) != 0)]
    return unit_figure("other", "Other columns", rest, engine, dimension)


def unit_figure(stem, title, columns, engine, dimension):
    """A figure with one panel per unit for the given columns."""
    by_unit = {}
    for c in columns:
        by_unit.setdefault(column_unit(c, engine, dimension) or "?", []).append(c)
    return figure(stem, title, [panel(", ".join(cs) if len(cs) == 1 else "value", u, cs)
                                for u, cs in by_unit.items()])


def axis_label(text, unit):
    if unit in (None, "?"):
        return text
    return f"{text} [{unit}]"


def draw(fig_spec, data, suptitle, logx, out_path, plt, np):
    """Render one figure spec to a PNG (stacked panels sharing the time axis)."""
    panels = fig_spec["panels"]
    fig, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False,
                             figsize=(8.5, 2.3 + 2.4 * len(panels)), layout="constrained")
    t = data["time"]
    for ax, p in zip(axes[:, 0], panels):
        zero = [c for c in p["columns"] if not np.any(np.nan_to_num(data[c]) != 0)]
        columns = [c for c in p["columns"] if c not in zero] or p["columns"]
        if len(columns) == len(p["columns"]):
            zero = []
        for k, c in enumerate(p["columns"]):
            if c not in columns:
                continue
            style = {"color": f"C{k % 10}", "lw": 1.6, "label": label_of(c)}
            style.update(STYLES.get(c, {}))
            style.update(p["styles"].get(c, {}))
            y = data[c]
            if p["logy"]:
                y = np.where(y > 0, y, np.nan)
            ax.plot(t, y, **style)
        if p["extra"]:
            p["extra"](ax)
        if p["logy"] and _has_positive(ax, np):
            ax.set_yscale("log")
        ax.set_ylabel(axis_label(p["ylabel"], p["unit"]))
        ax.grid(True, alpha=0.3)
        handles, labels = ax.get_legend_handles_labels()
        if handles:
            title = "zero throughout: " + ", ".join(label_of(c) for c in zero) if zero else None
            ax.legend(fontsize="small", loc="best", ncol=2 if len(handles) > 5 else 1,
                      title=title, title_fontsize="small")
    if logx and np.any(t > 0):
        axes[-1, 0].set_xscale("log")
        axes[-1, 0].set_xlim(t[t > 0].min(), t.max())
    axes[-1, 0].set_xlabel("time t [s]")
    fig.suptitle(f"{fig_spec['title']}\n{suptitle}", fontsize="medium")
    fig.savefig(out_path, dpi=150)
    plt.close(fig)


def _has_positive(ax, np):
    for line in ax.get_lines():
        y = np.asarray(line.get_ydata(), dtype=float)
        if np.any(np.isfinite(y) & (y > 0)):
            return True
    return False


def parse_window(text):
    try:
        a, b = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError("expected t1,t2 in seconds, e.g. 0,30")
    if not b > a:
        raise argparse.ArgumentTypeError("t2 must exceed t1")
    return (a, b)


def parse_args(argv):
    p = argparse.ArgumentParser(
        description="Plot OUTDIR/series.csv of a granulab run as PNG figures "
                    "(energies, contacts, wall forces, mass flow; edmd: temperature with "
                    "Haff's law, collisions, pressure, clusters).",
        epilog="example: python3 scripts/plot_series.py out/disks_in_box")
    p.add_argument("outdir", help="output folder of `granulab run` (holds series.csv)")
    p.add_argument("--out", help="folder for the PNGs (default: OUTDIR)")
    p.add_argument("--columns", help="plot only these columns (comma-separated) in one figure, "
                                     "series_columns.png")
    p.add_argument("--haff-window", type=parse_window, metavar="T1,T2",
                   help="edmd: fit Haff's law to the rows with T1 <= t <= T2 [s] "
                        "(default: tau <= tau_hc from summary.json, else all rows)")
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    np, _, plt = import_plotting()
    plt.rcParams.update({"font.size": 11, "axes.titlesize": 12, "legend.fontsize": 9})
    try:
        header, data = read_series(os.path.join(args.outdir, "series.csv"), np)
        summary = read_summary(os.path.join(args.outdir, "summary.json"), header)
    except InputError as e:
        print(f"plot_series: {e}", file=sys.stderr)
        return EXIT_INPUT
    engine = summary.get("engine", "dem")
    dimension = summary.get("dimension", 2)
    if args.columns:
        wanted = [c.strip() for c in args.columns.split(",") if c.strip()]
        unknown = [c for c in wanted if c not in header]
        if unknown:
            print(f"plot_series: no column {', '.join(unknown)} in series.csv; columns: "
                  f"{', '.join(header)}", file=sys.stderr)
            return EXIT_INPUT
        figs = [unit_figure("columns", "Selected columns", wanted, engine, dimension)]
    elif engine == "edmd":
        figs = edmd_figures(header, data, summary, args, np)
    else:
        figs = dem_figures(header, data, np)
    if not args.columns:
        figs.append(other_figure(header, data, figs, engine, dimension, np))
    out_dir = args.out or args.outdir
    os.makedirs(out_dir, exist_ok=True)
    scene = os.path.basename(str(summary.get("scene", ""))) or os.path.basename(
        os.path.normpath(args.outdir))
    status = summary.get("status")
    suptitle = f"{scene} ({engine}{', ' + status if status and status != 'completed' else ''})"
    logx = engine == "edmd" and log_spaced(data["time"], np)
    for f in figs:
        if not f["panels"]:
            continue
        path = os.path.join(out_dir, f"series_{f['stem']}.png")
        draw(f, data, suptitle, logx, path, plt, np)
        print(path)
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
