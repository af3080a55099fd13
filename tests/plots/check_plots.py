#!/usr/bin/env python3
"""CTest driver of scripts/plot_series.py, plot_analysis.py and plot_particle_series.py (label cli).

Usage: python3 tests/plots/check_plots.py series|analysis|errors|particles WORKDIR

series    plots the fixtures dem_silo/ and edmd_cooling/ (trimmed real series.csv and
          summary.json) and checks the expected PNGs
analysis  plots every table of fixtures/analysis/ (made by make_fixtures.py) and checks the
          expected PNGs
errors    missing folder, missing table, malformed header, non-numeric cell, ragged row,
          a run without CSV/ (plot_particle_series.py): exit status 2 and a message naming
          the file
particles writes a small run folder with CSV/*.csv in the long format (time,id,<quantity>;
          three particles, one entering late and one leaving early, a cut last row) into
          WORKDIR and plots it with plot_particle_series.py: all ids, --ids, more than 20
          particles (a note), an unknown id (exit 2)
A PNG passes when it has the PNG signature and an IHDR chunk, is at least 600 x 400 pixels and
larger than 8 kB. Exit status 77 (CTest SKIP_RETURN_CODE) when matplotlib or numpy is missing.
"""
import os
import shutil
import struct
import subprocess
import sys

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
FIXTURES = os.path.join(HERE, "fixtures")
SCRIPTS = os.path.join(ROOT, "scripts")


def png_size(path):
    """(width, height) of a PNG file, or raise ValueError."""
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        raise ValueError(f"{path}: not a PNG file")
    return struct.unpack(">II", head[16:24])


def check_png(path, failures):
    if not os.path.isfile(path):
        failures.append(f"missing {path}")
        return
    try:
        width, height = png_size(path)
    except ValueError as e:
        failures.append(str(e))
        return
    size = os.path.getsize(path)
    if width < 600 or height < 400 or size < 8000:
        failures.append(f"{path}: {width} x {height} pixels, {size} bytes: too small")


def run(args, expect):
    cmd = [sys.executable] + args
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != expect:
        print(f"FAIL: {' '.join(cmd)} exited {r.returncode}, expected {expect}\n"
              f"stdout:\n{r.stdout}\nstderr:\n{r.stderr}")
        return None
    return r


def fresh(work, name):
    path = os.path.join(work, name)
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


def check_series(work):
    failures = []
    expected = {
        "dem_silo": ["energies", "contacts", "walls", "flow"],
        "edmd_cooling": ["energies", "temperature", "collisions", "pressure", "velocity",
                         "clusters"],
    }
    for run_name, figures in expected.items():
        out = fresh(work, "series_" + run_name)
        r = run([os.path.join(SCRIPTS, "plot_series.py"), os.path.join(FIXTURES, run_name),
                 "--out", out], 0)
        if r is None:
            return 1
        for f in figures:
            check_png(os.path.join(out, f"series_{f}.png"), failures)
        if run_name == "edmd_cooling" and "Haff fit" in r.stderr:
            failures.append("no Haff fit on the cooling gas: " + r.stderr)
    out = fresh(work, "series_columns")
    if run([os.path.join(SCRIPTS, "plot_series.py"), os.path.join(FIXTURES, "dem_silo"),
            "--out", out, "--columns", "particles,mass,wall_left_fy"], 0) is None:
        return 1
    check_png(os.path.join(out, "series_columns.png"), failures)
    return report(failures)


def check_analysis(work):
    failures = []
    out = fresh(work, "analysis")
    r = run([os.path.join(SCRIPTS, "plot_analysis.py"), os.path.join(FIXTURES, "analysis"),
             "--out", out], 0)
    if r is None:
        return 1
    expected = ["floor_pressure", "force_directions", "force_magnitudes", "coordination",
                "repose_profile", "roughness_spectrum", "janssen", "packing_rho_rel",
                "strain_eps_xx", "strain_eps_xz", "stress_principal"]
    expected += [f"stress_{c}" for c in ("sigma_xx", "sigma_zz", "sigma_xz", "sigma_major",
                                         "sigma_minor", "psi_deg")]
    for f in expected:
        check_png(os.path.join(out, f + ".png"), failures)
    if "3 bins had no contacts" not in r.stderr:
        failures.append("the warning note of floor_pressure was not printed to stderr")
    out = fresh(work, "analysis_one")
    if run([os.path.join(SCRIPTS, "plot_analysis.py"), os.path.join(FIXTURES, "analysis"),
            "janssen", "coordination.csv", "--out", out], 0) is None:
        return 1
    if sorted(os.listdir(out)) != ["coordination.png", "janssen.png"]:
        failures.append(f"named tables: wrote {sorted(os.listdir(out))}")
    return report(failures)


def check_errors(work):
    bad = fresh(work, "bad")
    with open(os.path.join(bad, "no_units.csv"), "w") as f:
        f.write("x,p\n0,1\n")
    with open(os.path.join(bad, "letters.csv"), "w") as f:
        f.write("# k = 0.64\nx [m],p [Pa]\n0,1\n1,abc\n")
    with open(os.path.join(bad, "ragged.csv"), "w") as f:
        f.write("x [m],p [Pa]\n0,1\n1\n")
    run_dir = fresh(work, "bad_run")
    with open(os.path.join(run_dir, "series.csv"), "w") as f:
        f.write("time,kinetic_energy\n0,1\nx,2\n3,4\n")
    cases = [
        ([os.path.join(SCRIPTS, "plot_series.py"), os.path.join(work, "no_such_run")],
         "series.csv"),
        ([os.path.join(SCRIPTS, "plot_series.py"), run_dir], "series.csv:3"),
        ([os.path.join(SCRIPTS, "plot_series.py"), os.path.join(FIXTURES, "dem_silo"),
          "--out", fresh(work, "bad_columns"), "--columns", "no_such_column"], "no_such_column"),
        ([os.path.join(SCRIPTS, "plot_analysis.py"), os.path.join(work, "no_such_folder")],
         "no_such_folder"),
        ([os.path.join(SCRIPTS, "plot_analysis.py"), bad, "missing_table"], "missing_table"),
        ([os.path.join(SCRIPTS, "plot_analysis.py"), bad, "no_units"], "no_units.csv:1"),
        ([os.path.join(SCRIPTS, "plot_analysis.py"), bad, "letters"], "letters.csv:4"),
        ([os.path.join(SCRIPTS, "plot_analysis.py"), bad, "ragged"], "ragged.csv:3"),
        ([os.path.join(SCRIPTS, "plot_particle_series.py"), run_dir],
         "output.particle_series = true"),
    ]
    failures = []
    for args, needle in cases:
        r = run(args, 2)
        if r is None:
            failures.append(f"exit status of {' '.join(args[-2:])}")
        elif needle not in r.stderr:
            failures.append(f"message of {' '.join(args[-2:])} lacks '{needle}': {r.stderr}")
    return report(failures)


QUANTITIES = ["r_x", "r_y", "phi", "v_x", "v_y", "omega", "a_x", "a_y", "alpha"]


def write_particle_run(folder, n_particles, cut_last_row=False):
    """A fake run folder with CSV/<q>.csv in the long format: particle i lives from
    t = 0.1 i (for i < 3; later ones from 0) to 2 s (particle 1 leaves at 1.2 s)."""
    import math
    csv_dir = os.path.join(folder, "CSV")
    os.makedirs(csv_dir, exist_ok=True)
    for k, q in enumerate(QUANTITIES):
        with open(os.path.join(csv_dir, q + ".csv"), "w") as f:
            f.write(f"time,id,{q}\n")
            for step in range(41):
                t = 0.05 * step
                for i in range(n_particles):
                    if (i < 3 and t < 0.1 * i - 1e-12) or (i == 1 and t > 1.2 + 1e-12):
                        continue
                    v = math.sin(1.3 * t + 0.4 * i + k) * (1 + 0.1 * i) + 0.5 * k
                    f.write(f"{t:.17g},{i},{v:.17g}\n")
            if cut_last_row:
                f.write("2.05,0")
    with open(os.path.join(folder, "summary.json"), "w") as f:
        f.write('{"engine": "dem", "scene": "fixture.toml"}\n')


def check_particles(work):
    failures = []
    small = fresh(work, "particles_small")
    write_particle_run(small, 3, cut_last_row=True)
    script = os.path.join(SCRIPTS, "plot_particle_series.py")
    r = run([script, small], 0)
    if r is None:
        return 1
    check_png(os.path.join(small, "particle_series.png"), failures)
    if "incomplete last row" not in r.stderr:
        failures.append("the cut last row was not reported: " + r.stderr)
    out = os.path.join(work, "particles_ids.png")
    if run([script, small, "--ids", "2,0", "--out", out], 0) is None:
        return 1
    check_png(out, failures)
    many = fresh(work, "particles_many")
    write_particle_run(many, 25)
    r = run([script, many], 0)
    if r is None:
        return 1
    check_png(os.path.join(many, "particle_series.png"), failures)
    if "first 20 of 25" not in r.stderr:
        failures.append("no note about drawing 20 of 25 particles: " + r.stderr)
    r = run([script, small, "--ids", "7"], 2)
    if r is None:
        failures.append("an unknown id did not exit 2")
    elif "no particle id 7" not in r.stderr:
        failures.append("message of an unknown id: " + r.stderr)
    return report(failures)


def report(failures):
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


def main(argv):
    if len(argv) != 3 or argv[1] not in ("series", "analysis", "errors", "particles"):
        print(__doc__, file=sys.stderr)
        return 2
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        print(f"skipped: {e} (install python3-matplotlib python3-numpy)")
        return SKIP
    work = os.path.abspath(argv[2])
    os.makedirs(work, exist_ok=True)
    return {"series": check_series, "analysis": check_analysis,
            "errors": check_errors, "particles": check_particles}[argv[1]](work)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
