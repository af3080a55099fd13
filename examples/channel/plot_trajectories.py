#!/usr/bin/python3
"""Draw the droplets' trajectories over the air speed of the channel example.

    /usr/bin/python3 examples/channel/plot_trajectories.py OUT [--time T] [--ids 0,5,...]
        [--scene FILE] [--png FILE]

OUT is the folder of examples/channel/run.sh (default out/channel). Reads
  OUT/case/<time>/C and OUT/case/<time>/U  the cell centres and the air velocity of the last
      time folder (or --time T), ASCII OpenFOAM files (controlDict: writeFormat ascii);
      C comes from `postProcess -func writeCellCentres -latestTime` (run.sh does it). The
      boundary faces are added with their values (noSlip and fixedValue patches: their value,
      zeroGradient: the nearest cell's), so the colours reach the walls;
  OUT/granulab/CSV/r_x.csv, r_y.csv  (output.particle_series = true, long format: header
      `time,id,r_x`, one row per particle per output time): one thin line per particle id;
  OUT/granulab/final.csv  where the particles still in the channel are at the end (dots);
  the scene (--scene, default particles.toml beside this script): its [[wall]] polylines
      (channel walls, obstacle) drawn in black, closed ones filled.
Draws the speed |U| [m/s] as a colour map (tricontourf on the cell and boundary-face centres)
with white streamlines, the walls and the trajectories; writes OUT/trajectories.png (or --png).
Without the vtk module: only numpy, matplotlib and Python's tomllib.
"""
import argparse
import csv
import os
import re
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.path import Path  # noqa: E402

# The reader of granulab's CSV/ series lives with scripts/plot_particle_series.py.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import plot_particle_series as particle_series  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def fail(msg):
    print(f"plot_trajectories.py: {msg}", file=sys.stderr)
    sys.exit(2)


# ---------------------------------------------------------------- OpenFOAM ASCII fields
def vectors(text, where):
    """The vectors of an OpenFOAM value: 'uniform (a b c)', 'nonuniform List<vector> N (...)'
    or the compact 'N{(a b c)}'. Returns an (N, 3) array, or (1, 3) for uniform."""
    text = text.strip()
    m = re.match(r"uniform\s*\(([^)]*)\)", text)
    if m:
        return np.array([[float(v) for v in m.group(1).split()]])
    m = re.match(r"nonuniform\s+List<vector>\s*(\d+)\s*\{\s*\(([^)]*)\)\s*\}", text)
    if m:
        return np.tile([float(v) for v in m.group(2).split()], (int(m.group(1)), 1))
    m = re.match(r"nonuniform\s+List<vector>\s*(\d+)\s*\(", text)
    if not m:
        fail(f"{where}: cannot read the value '{text[:60]}...'")
    n = int(m.group(1))
    body = text[m.end():]
    end = body.rfind(")")
    nums = np.array(body[:end].replace("(", " ").replace(")", " ").split(), dtype=float)
    if nums.size != 3 * n:
        fail(f"{where}: expected {n} vectors, read {nums.size / 3:g}")
    return nums.reshape(n, 3)


def read_vector_field(path):
    """(internal (N, 3) array, {patch: (type, value text or None)}) of an ASCII volVectorField."""
    if not os.path.isfile(path):
        return None
    with open(path, errors="replace") as f:
        text = f.read()
    fmt = re.search(r"format\s+(\w+)\s*;", text)
    if fmt and fmt.group(1) != "ascii":
        fail(f"{path}: format {fmt.group(1)}; set writeFormat ascii in system/controlDict (or "
             f"run `foamFormatConvert` after setting it)")
    m = re.search(r"internalField\s+(.*?);\s*\n\s*boundaryField", text, re.S)
    if not m:
        fail(f"{path}: no internalField ... boundaryField")
    internal = vectors(m.group(1), f"{path} internalField")
    patches = {}
    rest = text[m.end():]
    pos = rest.find("{") + 1
    while True:
        pm = re.compile(r"\s*([\w.\-\"]+)\s*\{").match(rest, pos)
        if not pm:
            break
        depth, k = 1, pm.end()
        while depth and k < len(rest):
            depth += {"{": 1, "}": -1}.get(rest[k], 0)
            k += 1
        block = rest[pm.end():k - 1]
        ptype = re.search(r"type\s+(\w+)\s*;", block)
        value = re.search(r"\bvalue\s+(.*?\))\s*;", block, re.S)
        patches[pm.group(1).strip('"')] = (ptype.group(1) if ptype else "?",
                                           value.group(1) if value else None)
        pos = k
    return internal, patches


def latest_time(case, wanted):
    """The time folder name (its C and U files exist) to read."""
    times = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(case, name, "U")):
            times.append((t, name))
    if not times:
        fail(f"{case}: no time folder with a field U (did icoFoam run?)")
    if wanted is not None:
        for t, name in times:
            if abs(t - wanted) <= 1e-9 * max(1.0, abs(wanted)):
                return t, name
        fail(f"{case}: no time folder {wanted:g} (times {min(times)[0]:g} ... {max(times)[0]:g})")
    return max(times)


def read_flow(case, wanted_time):
    """Points (x, y) and velocity (ux, uy) of the cells and boundary faces at one time."""
    t, name = latest_time(case, wanted_time)
    folder = os.path.join(case, name)
    cfile, ufile = os.path.join(folder, "C"), os.path.join(folder, "U")
    c = read_vector_field(cfile)
    if c is None:
        fail(f"{cfile} not found: run `postProcess -func writeCellCentres -time {name}` in "
             f"{case} (with the OpenFOAM environment sourced; run.sh does it)")
    u = read_vector_field(ufile)
    (cc, cpatch), (uc, upatch) = c, u
    if len(cc) != len(uc):
        fail(f"{folder}: {len(cc)} cell centres but {len(uc)} velocities")
    xy, uv = [cc[:, :2]], [uc[:, :2]]
    for patch, (ctype, cvalue) in cpatch.items():
        if cvalue is None or patch not in upatch:
            continue  # empty (front and back) patches carry no faces
        faces = vectors(cvalue, f"{cfile} patch {patch}")[:, :2]
        utype, uvalue = upatch[patch]
        if utype == "noSlip":
            vel = np.zeros_like(faces)
        elif uvalue is not None:  # fixedValue and any patch type that writes its value
            vel = vectors(uvalue, f"{ufile} patch {patch}")[:, :2]
            vel = np.broadcast_to(vel, faces.shape) if len(vel) == 1 else vel
        else:  # zeroGradient and the like: the value of the nearest cell
            near = np.empty(len(faces), dtype=int)
            for s in range(0, len(faces), 256):
                d = ((faces[s:s + 256, None, :] - cc[None, :, :2]) ** 2).sum(axis=2)
                near[s:s + 256] = np.argmin(d, axis=1)
            vel = uc[near, :2]
        if len(vel) != len(faces):
            fail(f"{folder}: patch {patch}: {len(faces)} faces but {len(vel)} values")
        xy.append(faces)
        uv.append(np.asarray(vel))
    return t, len(cc), np.concatenate(xy), np.concatenate(uv)


# ---------------------------------------------------------------- granulab output
def read_long(path, quantity):
    """{id: (time, values)} of a long-format particle series file `time,id,<quantity>`."""
    if not os.path.isfile(path):
        fail(f"{path} not found: run granulab with output.particle_series = true "
             f"(particles.toml sets it)")
    try:
        return particle_series.read_long(path, quantity, np, allow_empty=True)
    except particle_series.InputError as e:
        fail(str(e))


def read_walls(scene):
    """[(name, (K, 2) points, closed)] of the scene's [[wall]] polylines, or []."""
    if not scene or not os.path.isfile(scene):
        print(f"plot_trajectories.py: scene {scene} not found; no walls drawn", file=sys.stderr)
        return []
    with open(scene, "rb") as f:
        doc = tomllib.load(f)
    walls = []
    for w in doc.get("wall", []):
        pts = np.array(w.get("points", []), dtype=float)
        if pts.ndim == 2 and len(pts) >= 2:
            walls.append((w.get("name", "wall"), pts[:, :2], bool(w.get("closed", False))))
    return walls


def parse_ids(text):
    try:
        return [int(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected comma-separated ids, got '{text}'")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", nargs="?", default="out/channel", help="run.sh output folder")
    ap.add_argument("--time", type=float, default=None,
                    help="the OpenFOAM time to draw [s] (default: the last)")
    ap.add_argument("--ids", type=parse_ids, default=None,
                    help="draw only these particle ids (default: all)")
    ap.add_argument("--scene", default=os.path.join(HERE, "particles.toml"),
                    help="the granulab scene with the [[wall]]s (default: particles.toml here)")
    ap.add_argument("--png", default=None, help="output picture (default OUT/trajectories.png)")
    a = ap.parse_args()

    case = os.path.join(a.out, "case")
    run = os.path.join(a.out, "granulab")
    if not os.path.isdir(case):
        fail(f"{case}: no such folder (the OpenFOAM case of run.sh)")
    t_flow, ncells, xy, uv = read_flow(case, a.time)
    speed = np.hypot(uv[:, 0], uv[:, 1])
    walls = read_walls(a.scene)
    rx = read_long(os.path.join(run, "CSV", "r_x.csv"), "r_x")
    ry = read_long(os.path.join(run, "CSV", "r_y.csv"), "r_y")
    ids = sorted(set(rx) & set(ry))
    if a.ids is not None:
        unknown = [i for i in a.ids if i not in ids]
        if unknown:
            fail(f"no particle id {', '.join(map(str, unknown))} in {run}/CSV")
        ids = a.ids

    # triangulation of the points; triangles across a hole (the obstacle) or with an edge much
    # longer than the mesh spacing are masked
    tri = mtri.Triangulation(xy[:, 0], xy[:, 1])
    tx, ty = xy[tri.triangles, 0], xy[tri.triangles, 1]
    edges = np.hypot(tx - np.roll(tx, 1, axis=1), ty - np.roll(ty, 1, axis=1))
    mask = edges.max(axis=1) > 3.0 * np.median(edges.min(axis=1))
    cen = np.column_stack([tx.mean(axis=1), ty.mean(axis=1)])
    for _, pts, closed in walls:
        if closed and len(pts) >= 3:
            mask |= Path(pts).contains_points(cen)
    tri.set_mask(mask)

    x0, x1 = xy[:, 0].min(), xy[:, 0].max()
    y0, y1 = xy[:, 1].min(), xy[:, 1].max()
    width, height = x1 - x0, y1 - y0
    fig_w = 14.0
    fig, ax = plt.subplots(figsize=(fig_w, max(3.5, 0.88 * fig_w * height / width + 2.1)),
                           layout="constrained")
    levels = np.linspace(0.0, float(speed.max()) * 1.0001, 25)
    cmap = matplotlib.colors.LinearSegmentedColormap.from_list(
        "speed", plt.get_cmap("YlGnBu")(np.linspace(0.0, 0.8, 256)))
    cf = ax.tricontourf(tri, speed, levels=levels, cmap=cmap)
    cb = fig.colorbar(cf, ax=ax, orientation="horizontal", fraction=0.08, pad=0.02,
                      aspect=50, ticks=np.arange(0.0, float(speed.max()) + 1e-9, 0.5))
    cb.set_label(f"air speed |U| [m/s] at t = {t_flow:g} s (OpenFOAM, {ncells} cells)")

    # streamlines on a regular grid, interpolated linearly from the triangulation
    nx = 400
    ny = max(20, int(round(nx * height / width)))
    gx, gy = np.meshgrid(np.linspace(x0, x1, nx), np.linspace(y0, y1, ny))
    gu = mtri.LinearTriInterpolator(tri, uv[:, 0])(gx, gy)
    gv = mtri.LinearTriInterpolator(tri, uv[:, 1])(gx, gy)
    more = {"broken_streamlines": False} if _has_broken() else {}
    ax.streamplot(gx, gy, gu, gv, density=(1.6, 0.6), color=(0.1, 0.1, 0.1, 0.35),
                  linewidth=0.6, arrowsize=0.7, **more)

    # trajectories
    for i in ids:
        (_, x), (_, y) = rx[i], ry[i]
        n = min(len(x), len(y))
        ax.plot(x[:n], y[:n], color="#b2182b", lw=0.4, alpha=0.6)
    left_inside = 0
    final = os.path.join(run, "final.csv")
    if os.path.isfile(final):
        with open(final, newline="") as f:
            rows = [r for r in csv.DictReader(f)
                    if a.ids is None or int(r["id"]) in a.ids]
        left_inside = len(rows)
        if rows:
            ax.plot([float(r["x"]) for r in rows], [float(r["y"]) for r in rows], "o",
                    ms=3.5, mfc="#b2182b", mec="k", mew=0.5, ls="none",
                    label=f"{len(rows)} still in the channel at the end", zorder=6)

    for name, pts, closed in walls:
        p = np.vstack([pts, pts[:1]]) if closed else pts
        if closed:
            ax.fill(pts[:, 0], pts[:, 1], color="0.55", zorder=4)
        ax.plot(p[:, 0], p[:, 1], color="k", lw=1.6, zorder=5, solid_capstyle="butt")
    steps = [np.median(np.diff(rx[i][0])) for i in ids[:50] if len(rx[i][0]) > 1]
    every = f", a point every {np.median(steps):.3g} s" if steps else ""
    ax.plot([], [], color="#b2182b", lw=1.2, label=f"droplet trajectories (granulab{every})")
    ax.plot([], [], color="0.55", lw=1.2, label=f"air streamlines at t = {t_flow:g} s")
    ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=3, fontsize=9,
              frameon=False, borderaxespad=0.2)

    ax.set_aspect("equal")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0 - 0.01 * height, y1 + 0.01 * height)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    t_last = max((float(rx[i][0][-1]) for i in ids), default=0.0)
    fig.suptitle(f"Droplets in a channel flow around a square obstacle: {len(ids)} trajectories "
                 f"(t = 0 ... {t_last:g} s) over the air speed")
    png = a.png or os.path.join(a.out, "trajectories.png")
    fig.savefig(png, dpi=130)
    print(f"flow at t = {t_flow:g} s: {ncells} cells, |U| max {speed.max():.3f} m/s; "
          f"{len(ids)} trajectories, {left_inside} particles still inside at the end")
    print(f"wrote {png}")


def _has_broken():
    """matplotlib >= 3.6 knows streamplot(broken_streamlines=...)."""
    major, minor = (int(v) for v in matplotlib.__version__.split(".")[:2])
    return (major, minor) >= (3, 6)


if __name__ == "__main__":
    main()
