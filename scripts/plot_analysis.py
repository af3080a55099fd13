#!/usr/bin/env python3
"""Plot the analysis tables of `granulab analyze` (OUTDIR/analysis/*.csv) as PNG figures.

Usage:
  python3 scripts/plot_analysis.py OUTDIR/analysis [TABLE ...] [--out DIR]

TABLE is a file name in the folder, with or without .csv, or a path; without any, every
*.csv of the folder whose header is in the table format is plotted (others are skipped with a
note). Table format (docs/plots.md): optional leading "# " notes ("# key = value unit" results,
a note starting with "warning" is a warning; others are remarks), a header of "name [unit]" cells (unit "1" for pure numbers),
then numeric rows ("nan" allowed). The file stem is the table name.

Generic rules, applied to any table:
  grid     first columns x and z (or x and y) forming a regular grid: one heat map per other
           column (<table>_<column>.png, equal aspect, colour bar "name [unit]"); with
           sigma_major, sigma_minor and psi_deg also <table>_principal.png, the principal axes
           drawn as line segments (psi: angle of the major axis from +x, counter-clockwise)
  polar    first column "alpha..." in rad: polar histogram of the other columns (<table>.png);
           a table covering only [0, pi] is mirrored to [pi, 2 pi] (axial directions)
  lines    otherwise every other column against the first (<table>.png), one panel per unit;
           "<c>_theory" dashed in the colour of <c>, "*_avg" thicker
Known tables get titles and axes: floor_pressure, wall_pressure*, force_directions,
force_magnitudes (linear and log P), coordination (bars), repose_profile (equal aspect, fits
dashed), roughness_spectrum (log-log), packing, stress, janssen, strain.
Result notes are shown in a box beside the plot; warnings go to stderr.
Exit status: 0 written, 2 missing or malformed table, 3 matplotlib or numpy missing.
"""
import argparse
import csv
import glob
import os
import re
import sys

EXIT_OK = 0
EXIT_INPUT = 2
EXIT_DEPENDENCY = 3

HEADER_CELL = re.compile(r"^\s*(?P<name>[^\[\]]*?)\s*\[(?P<unit>[^\[\]]*)\]\s*$")
RESULT_NOTE = re.compile(r"^(?P<key>[^=]+?)\s*=\s*"
                         r"(?P<value>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
                         r"|[-+]?nan|[-+]?inf)(?:\s+\[?(?P<unit>[^\s\[\]]+)\]?)?\s*$",
                         re.IGNORECASE)


class InputError(Exception):
    """A missing or malformed table; the message names the file and line."""


class NotATable(InputError):
    """A CSV file whose header is not in the table format (no "[unit]" cells)."""


class Table:
    """One analysis table: name (file stem), results [(key, value, unit)], warnings,
    columns [(name, unit)] and data (rows x columns float array)."""

    def __init__(self, name, path, results, warnings, columns, data):
        self.name = name
        self.path = path
        self.results = results
        self.warnings = warnings
        self.columns = columns
        self.data = data

    def names(self):
        return [c[0] for c in self.columns]

    def col(self, name):
        return self.data[:, self.names().index(name)]

    def unit(self, name):
        return self.columns[self.names().index(name)][1]


def read_table(path, np):
    """Parse one table file (see the module docstring); raises InputError when malformed."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    results, warnings = [], []
    k = 0
    while k < len(lines) and (lines[k].startswith("#") or not lines[k].strip()):
        text = lines[k][1:].strip() if lines[k].startswith("#") else ""
        k += 1
        if not text:
            continue
        m = RESULT_NOTE.match(text)
        if m:
            results.append((m.group("key"), float(m.group("value")), m.group("unit") or ""))
        elif text.lower().startswith("warning") or "fewer than" in text:
            warnings.append(text)  # other notes are remarks (settings, formulas): kept, not printed
    if k == len(lines):
        raise InputError(f"{path}: no header line (expected cells \"name [unit]\")")
    header_line = k + 1
    cells = next(csv.reader([lines[k]]))
    parsed = [HEADER_CELL.match(c) for c in cells]
    if not any(parsed):
        raise NotATable(f"{path}:{header_line}: header cells must be \"name [unit]\" "
                        f"(got '{lines[k][:60]}')")
    bad = [c for c, m in zip(cells, parsed) if not m or not m.group("name")]
    if bad:
        raise InputError(f"{path}:{header_line}: header cell '{bad[0]}' is not \"name [unit]\"")
    columns = [(m.group("name"), m.group("unit").strip() or "1") for m in parsed]
    if len({c[0] for c in columns}) != len(columns):
        raise InputError(f"{path}:{header_line}: repeated column names")
    rows = []
    for n, line in enumerate(lines[k + 1:], start=header_line + 1):
        if not line.strip():
            continue
        if line.startswith("#"):
            raise InputError(f"{path}:{n}: notes belong before the header")
        row = next(csv.reader([line]))
        if len(row) != len(columns):
            raise InputError(f"{path}:{n}: {len(row)} cells, the header has {len(columns)}")
        try:
            rows.append([float(c) for c in row])
        except ValueError:
            bad = next(c for c in row if not _is_number(c))
            raise InputError(f"{path}:{n}: '{bad}' is not a number")
    if not rows:
        raise InputError(f"{path}: no data rows after the header")
    name = os.path.splitext(os.path.basename(path))[0]
    return Table(name, path, results, warnings, columns, np.array(rows, dtype=float))


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def label(name, unit):
    return f"{name} [{unit}]"


def safe(name):
    return re.sub(r"[^A-Za-z0-9]+", "_", name).strip("_") or "column"


TITLES = {
    "floor_pressure": "Pressure on the floor",
    "wall_pressure": "Pressure on the wall",
    "force_directions": "Contact force directions P(α)",
    "force_magnitudes": "Contact force magnitudes P(F/<F>)",
    "coordination": "Coordination number distribution P(K)",
    "repose_profile": "Heap surface and angle of repose",
    "roughness_spectrum": "Surface roughness power spectrum",
    "packing": "Packing fraction",
    "stress": "Stress field",
    "janssen": "Janssen: stresses in the column",
    "strain": "Strain field",
}


def title_of(table):
    for key, title in TITLES.items():
        if table.name == key or (key == "wall_pressure" and table.name.startswith(key)):
            return f"{title} ({table.name})"
    return table.name.replace("_", " ")


def grid_of(table, np):
    """(x name, y name, xs, ys, index rows->(iy, ix)) when the first two columns form a
    regular grid, else None."""
    names = table.names()
    if len(names) < 3 or names[0] != "x" or names[1] not in ("z", "y"):
        return None
    x, y = table.data[:, 0], table.data[:, 1]
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y))):
        return None
    xs, ix = np.unique(x, return_inverse=True)
    ys, iy = np.unique(y, return_inverse=True)
    if len(xs) < 2 or len(ys) < 2 or len(xs) * len(ys) != len(x):
        return None
    if len(set(zip(ix.tolist(), iy.tolist()))) != len(x):
        return None
    return names[0], names[1], xs, ys, (iy, ix)


def edges(centres, np):
    """Cell edges around (possibly unevenly spaced) cell centres."""
    mid = (centres[1:] + centres[:-1]) / 2
    return np.concatenate([[2 * centres[0] - mid[0]], mid, [2 * centres[-1] - mid[-1]]])


DIVERGING = re.compile(r"(_xz|_xy|_yz|strain|_rate|^dx|^dz|^dy|^u_|^v_|_shear|rotation)",
                       re.IGNORECASE)


def colour_map(name, values, np, mpl):
    """Colour map and norm: cyclic for angles, diverging about 0 for signed fields."""
    finite = values[np.isfinite(values)]
    if name.endswith("_deg") or name.startswith(("psi", "angle", "theta")):
        return "twilight", None
    if finite.size and finite.min() < 0 < finite.max() or DIVERGING.search(name):
        top = float(np.max(np.abs(finite))) if finite.size else 1.0
        top = top or 1.0
        return "RdBu_r", mpl.colors.TwoSlopeNorm(vcenter=0.0, vmin=-top, vmax=top)
    return "viridis", None


def new_figure(plt, width, height):
    return plt.figure(figsize=(width, height), layout="constrained")


def heat_maps(table, grid, out_dir, plt, mpl, np):
    """One heat map per non-coordinate column, and the principal axes of a stress table."""
    xname, yname, xs, ys, (iy, ix) = grid
    xe, ye = edges(xs, np), edges(ys, np)
    width, height, bar_side = map_size(xe, ye)
    paths = []
    for name, unit in table.columns[2:]:
        field = np.full((len(ys), len(xs)), np.nan)
        field[iy, ix] = table.col(name)
        if not np.any(np.isfinite(field)):
            print(f"plot_analysis: {table.path}: column {name} is all nan; not drawn",
                  file=sys.stderr)
            continue
        cmap, norm = colour_map(name, field, np, mpl)
        cmap = mpl.colormaps[cmap].copy()
        cmap.set_bad("0.85")
        fig = new_figure(plt, width, height)
        ax = fig.add_subplot()
        mesh = ax.pcolormesh(xe, ye, np.ma.masked_invalid(field), cmap=cmap, norm=norm,
                             shading="flat")
        ax.set_aspect("equal")
        ax.set_xlabel(label(xname, table.unit(xname)))
        ax.set_ylabel(label(yname, table.unit(yname)))
        bar = fig.colorbar(mesh, ax=ax, location=bar_side, fraction=0.08, pad=0.03,
                           aspect=30)
        bar.set_label(label(name, unit))
        ax.set_title(f"{title_of(table)}: {name}{notes_line(table)}", fontsize="medium")
        paths.append(save(fig, out_dir, f"{table.name}_{safe(name)}", plt))
    names = table.names()
    if all(c in names for c in ("sigma_major", "sigma_minor", "psi_deg")):
        paths.append(principal_axes(table, grid, out_dir, plt, mpl, np))
    return paths


def map_size(xe, ye):
    """Figure (width, height) in inches fitting the domain's shape, and the colour bar side."""
    aspect = (ye[-1] - ye[0]) / (xe[-1] - xe[0])
    side = 6.5
    ax_w, ax_h = (side, side * aspect) if aspect <= 1 else (side / aspect, side)
    ax_w, ax_h = max(ax_w, 2.6), max(ax_h, 1.6)
    if aspect < 0.35:
        return max(ax_w + 1.4, 6.0), ax_h + 2.1, "bottom"
    return max(ax_w + 2.6, 5.5), ax_h + 1.6, "right"


def notes_line(table):
    """The results as a second title line ("" without results)."""
    if not table.results:
        return ""
    return "\n" + ", ".join(f"{k} = {v:.4g} {u}".rstrip() for k, v, u in table.results)


def principal_axes(table, grid, out_dir, plt, mpl, np):
    """Major (and minor) principal stress axes as centred line segments over sigma_major."""
    xname, yname, xs, ys, (iy, ix) = grid
    xe, ye = edges(xs, np), edges(ys, np)
    major = np.full((len(ys), len(xs)), np.nan)
    minor, psi = major.copy(), major.copy()
    major[iy, ix] = table.col("sigma_major")
    minor[iy, ix] = table.col("sigma_minor")
    psi[iy, ix] = np.radians(table.col("psi_deg"))
    width, height, bar_side = map_size(xe, ye)
    fig = new_figure(plt, width, height + 0.5)
    ax = fig.add_subplot()
    cmap = mpl.colormaps["Greys"].copy()
    cmap.set_bad("white")
    mesh = ax.pcolormesh(xe, ye, np.ma.masked_invalid(major), cmap=cmap, shading="flat",
                         alpha=0.45)
    scale = np.nanmax(np.abs(major))
    scale = scale if np.isfinite(scale) and scale > 0 else 1.0
    cell = min(np.min(np.diff(xs)), np.min(np.diff(ys)))
    gx, gy = np.meshgrid(xs, ys)
    for value, angle, colour, name in ((major, psi, "C3", "major axis σ_major"),
                                       (minor, psi + np.pi / 2, "C0", "minor axis σ_minor")):
        length = 0.9 * np.abs(value) / scale
        ok = np.isfinite(length) & np.isfinite(angle)
        ax.quiver(gx[ok], gy[ok], (length * np.cos(angle))[ok], (length * np.sin(angle))[ok],
                  color=colour, pivot="middle", angles="xy", scale_units="xy",
                  scale=1 / cell, headwidth=0, headlength=0, headaxislength=0,
                  width=0.004 if colour == "C3" else 0.003, label=name)
    ax.set_aspect("equal")
    ax.set_xlim(xe[0], xe[-1])
    ax.set_ylim(ye[0], ye[-1])
    ax.set_xlabel(label(xname, table.unit(xname)))
    ax.set_ylabel(label(yname, table.unit(yname)))
    bar = fig.colorbar(mesh, ax=ax, location=bar_side, fraction=0.08, pad=0.03, aspect=30)
    bar.set_label(label("sigma_major", table.unit("sigma_major")))
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.07 if bar_side == "right" else -0.5),
              ncol=2, fontsize="small")
    ax.set_title(f"{title_of(table)}: principal axes, length ∝ |σ|{notes_line(table)}",
                 fontsize="medium")
    return save(fig, out_dir, f"{table.name}_principal", plt)


def polar_plot(table, out_dir, plt, np):
    """Polar histogram of every other column against the angle column."""
    alpha = table.data[:, 0]
    order = np.argsort(alpha)
    alpha = alpha[order]
    width = np.median(np.diff(alpha)) if len(alpha) > 1 else 2 * np.pi
    mirrored = alpha.max() <= np.pi + width
    fig = new_figure(plt, 7.5, 6.2)
    ax = fig.add_subplot(projection="polar")
    for k, (name, unit) in enumerate(table.columns[1:]):
        if name in ("forces", "contacts", "grains") or name.startswith("count"):
            continue  # counts per bin have another scale than the density P [1/rad]
        values = table.data[order, k + 1]
        colour = f"C{k % 10}"
        theory = name.endswith("_theory")
        if theory:
            base = name[: -len("_theory")]
            colour = f"C{[c[0] for c in table.columns[1:]].index(base) % 10}" \
                if base in table.names() else colour
            a = np.concatenate([alpha, alpha + np.pi]) if mirrored else alpha
            v = np.concatenate([values, values]) if mirrored else values
            a, v = np.append(a, a[0] + 2 * np.pi), np.append(v, v[0])
            ax.plot(a, v, "--", color=colour, lw=2, label=label(name, unit))
            continue
        ax.bar(alpha, values, width=width, color=colour, alpha=0.75 if k == 0 else 0.45,
               edgecolor="white", linewidth=0.5, label=label(name, unit))
        if mirrored:
            ax.bar(alpha + np.pi, values, width=width, color=colour, alpha=0.3,
                   edgecolor="white", linewidth=0.5)
    ax.set_title(title_of(table) + ("\n(α and α + π are one direction: mirrored half lighter)"
                                    if mirrored else ""), fontsize="medium")
    ax.set_xlabel(label(table.columns[0][0], table.columns[0][1]), labelpad=10)
    ax.legend(loc="upper left", bbox_to_anchor=(1.05, 1.0), fontsize="small")
    add_notes(fig, ax, table, below_legend=True)
    return [save(fig, out_dir, table.name, plt)]


def colour_plan(names):
    """Colour per column: "<c>_theory" and "<c>_avg" take the colour of <c>."""
    colours, k = {}, 0
    for n in names:
        base = re.sub(r"_(theory|avg)$", "", n)
        if base in colours:
            colours[n] = colours[base]
            continue
        colours[n] = f"C{k % 10}"
        colours[base] = colours[n]
        k += 1
    return colours


def line_style(name, colour):
    style = {"color": colour, "lw": 1.6, "label": name}
    if name.endswith("_theory"):
        style.update(linestyle="--", lw=1.8)
    if name.endswith("_avg"):
        style.update(lw=3.0)
    return style


def line_plot(table, out_dir, plt, np):
    """Every other column against the first, one panel per unit (known tables adjusted)."""
    names = table.names()
    x_name = names[0]
    ys = names[1:]
    special = table.name
    if special.startswith("wall_pressure"):
        special = "floor_pressure"
    pressure_norm = special == "floor_pressure" and "x/d" in names
    if pressure_norm:  # the normalised pair replaces p against x
        x_name = "x/d"
        norm = [n for n in names if "/(rho g h)" in n]
        others = [n for n in names if n not in norm and n not in ("x", "x/d")
                  and table.unit(n) == "1"]
        ys = norm + others
    elif special == "repose_profile":
        ys = [n for n in names[1:]]
    groups = {}
    for n in ys:  # one panel per unit; counts ("contacts", "count*") get their own
        own = n == "contacts" or n.startswith("count")
        groups.setdefault((table.unit(n), n if own else ""), []).append(n)
    panels = [(u, cs) for (u, _), cs in groups.items()]
    log_copy = special == "force_magnitudes"
    if log_copy:
        panels = panels + [(u, cs) for (u, _), cs in groups.items()]
    x = table.col(x_name)
    order = np.argsort(x, kind="stable")
    x = x[order]
    colours = colour_plan(ys)
    height = 1.8 + 3.0 * len(panels)
    equal = False  # repose_profile: the true shape when the heap is not too flat to read
    if special == "repose_profile":
        span = np.nanmax(table.data[:, 1:]) - min(0.0, np.nanmin(table.data[:, 1:]))
        equal = span / max(np.ptp(x), 1e-300) >= 0.15
        height = min(8.0, max(3.2, 1.8 + 6.5 * span / max(np.ptp(x), 1e-300))) if equal else 4.5
    fig = new_figure(plt, 8.5 if special != "repose_profile" else 9.5, height)
    axes = fig.subplots(len(panels), 1, sharex=True, squeeze=False)[:, 0]
    for k, (ax, (unit, cols)) in enumerate(zip(axes, panels)):
        logy = special == "roughness_spectrum" or (log_copy and k >= len(groups))
        bars = special == "coordination" or (special == "floor_pressure" and cols == ["contacts"])
        for n in cols:
            y = table.col(n)[order]
            if logy:
                y = np.where(y > 0, y, np.nan)
            if not np.any(np.isfinite(y)):
                print(f"plot_analysis: {table.path}: column {n} is all nan; not drawn",
                      file=sys.stderr)
                continue
            style = line_style(n, colours[n])
            if bars and not n.endswith("_theory"):
                step = np.median(np.diff(x)) if len(x) > 1 else 1.0
                ax.bar(x, y, width=0.8 * step, color=style["color"], alpha=0.8, label=n)
            elif special == "repose_profile" and n == "h":
                ax.plot(x, y, "o", ms=3, color=style["color"], label="surface h(x)")
            else:
                if special == "repose_profile" and n.startswith("fit"):
                    style.update(linestyle="--", lw=2.2, color="k" if "left" in n else "C3")
                ax.plot(x, y, **style)
        if logy:
            ax.set_yscale("log")
        if special == "roughness_spectrum":
            ax.set_xscale("log")
        ylab = ", ".join(cols) if len(cols) <= 2 else "value"
        if special == "repose_profile":
            if equal:
                ax.set_aspect("equal", adjustable="box")
            ylab = "height" if equal else "height (vertical scale exaggerated)"
        ax.set_ylabel(label(ylab, unit) + (" (log)" if logy and log_copy else ""))
        ax.grid(True, alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize="small", loc="best")
    axes[-1].set_xlabel(label(x_name, table.unit(x_name)))
    if special == "roughness_spectrum":
        axes[-1].set_xscale("log")
    axes[0].set_title(title_of(table))
    add_notes(fig, axes[0], table)
    return [save(fig, out_dir, table.name, plt)]


def add_notes(fig, ax, table, below_legend=False):
    """The table's "key = value unit" results in a box to the right of the axes."""
    if not table.results:
        return
    text = "\n".join(f"{k} = {v:.4g} {u}".rstrip() for k, v, u in table.results)
    if below_legend:
        ax.text(1.05, 0.0, text, transform=ax.transAxes, va="bottom", ha="left",
                fontsize="small", bbox={"boxstyle": "round", "fc": "0.96", "ec": "0.6"})
    else:
        ax.text(1.02, 1.0, text, transform=ax.transAxes, va="top", ha="left",
                fontsize="small", bbox={"boxstyle": "round", "fc": "0.96", "ec": "0.6"})


def save(fig, out_dir, stem, plt):
    path = os.path.join(out_dir, stem + ".png")
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path


def plot_table(table, out_dir, plt, mpl, np):
    """PNG paths of one table, by the generic rules (grid, polar, lines)."""
    for w in table.warnings:
        print(f"plot_analysis: {table.name}: {w}", file=sys.stderr)
    grid = grid_of(table, np)
    if grid:
        return heat_maps(table, grid, out_dir, plt, mpl, np)
    first, unit = table.columns[0]
    if unit == "rad" and first.startswith("alpha"):
        return polar_plot(table, out_dir, plt, np)
    if len(table.columns) < 2:
        raise InputError(f"{table.path}: one column only, nothing to plot against it")
    return line_plot(table, out_dir, plt, np)


def table_paths(folder, names):
    """(explicit, paths): the named tables, or every *.csv of the folder."""
    if not os.path.isdir(folder):
        raise InputError(f"{folder}: no such folder (run `granulab analyze OUTDIR` first)")
    if not names:
        paths = sorted(glob.glob(os.path.join(folder, "*.csv")))
        if not paths:
            raise InputError(f"{folder}: no .csv tables")
        return False, paths
    paths = []
    for n in names:
        candidates = [n, os.path.join(folder, n), os.path.join(folder, n + ".csv")]
        found = next((c for c in candidates if os.path.isfile(c)), None)
        if found is None:
            raise InputError(f"{os.path.join(folder, n)}: no such table")
        paths.append(found)
    return True, paths


def import_plotting():
    """numpy and matplotlib (Agg backend), or exit 3 with the Debian packages to install."""
    try:
        import numpy
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as pyplot
    except ImportError as e:
        print(f"plot_analysis: {e}; install python3-matplotlib and python3-numpy "
              "(scripts/setup.sh does)", file=sys.stderr)
        sys.exit(EXIT_DEPENDENCY)
    return numpy, matplotlib, pyplot


def parse_args(argv):
    p = argparse.ArgumentParser(
        description="Plot the analysis tables (OUTDIR/analysis/*.csv) of `granulab analyze` "
                    "as PNG figures: heat maps for x-z grids, polar histograms for angles, "
                    "line plots otherwise.",
        epilog="example: python3 scripts/plot_analysis.py out/heap/analysis floor_pressure")
    p.add_argument("folder", help="the analysis folder (OUTDIR/analysis)")
    p.add_argument("tables", nargs="*", help="tables to plot: names in the folder (with or "
                                             "without .csv) or paths; default all")
    p.add_argument("--out", help="folder for the PNGs (default: next to the tables)")
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    np, mpl, plt = import_plotting()
    plt.rcParams.update({"font.size": 11, "axes.titlesize": 12, "legend.fontsize": 9})
    try:
        explicit, paths = table_paths(args.folder, args.tables)
        tables = []
        for path in paths:
            try:
                tables.append(read_table(path, np))
            except NotATable as e:
                if explicit:
                    raise
                print(f"plot_analysis: skipped {e}", file=sys.stderr)
        if not tables:
            raise InputError(f"{args.folder}: no table in the format of docs/plots.md")
        for table in tables:
            out_dir = args.out or os.path.dirname(os.path.abspath(table.path))
            os.makedirs(out_dir, exist_ok=True)
            for path in plot_table(table, out_dir, plt, mpl, np):
                print(path)
    except InputError as e:
        print(f"plot_analysis: {e}", file=sys.stderr)
        return EXIT_INPUT
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
