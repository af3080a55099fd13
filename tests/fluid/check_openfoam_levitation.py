#!/usr/bin/python3
"""CI integration test with a real CFD program (issue 14, cfddem spec T6): OpenFOAM computes the
vertical air stream of examples/levitation on a coarse 20 x 20 mesh (blockMesh, icoFoam,
foamToVTK; under a second here), granulab flies the polystyrene ball in it, and the test checks
  1. that granulab read every time step foamToVTK wrote (the .series index lists them; summary.json
     counts the fields and the loads, series.csv's fluid_field reaches the last one), and
  2. that the ball's speed relative to the air at its position (final.csv's fluid_uy minus vy) is
     the terminal speed of the quadratic drag law, v = sqrt(8/3 R g (rho_p - rho_f)/(rho_f c_w)),
     within 1 % after 5 s (the flow is steady after ~0.5 s; the ball's own acceleration as it
     rises through the slowly varying stream shifts the balance by < 0.1 %).
Usage: check_openfoam_levitation.py GRANULAB_BINARY WORKDIR. Exit 0 pass, 1 fail."""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, "..", ".."))


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def main():
    binary, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    r = subprocess.run([os.path.join(root, "examples/levitation/run.sh"), "--cells", "20", "--out", work, "--cfd-only"],
                       capture_output=True, text=True)
    print(r.stdout[-2000:], r.stderr[-2000:])
    if r.returncode != 0:
        fail("the OpenFOAM part of examples/levitation/run.sh failed")
    vtk = os.path.join(work, "case", "VTK")
    series = [f for f in os.listdir(vtk) if f.endswith(".series")]
    if len(series) != 1:
        fail(f"expected one .series index in {vtk}, found {series}")
    with open(os.path.join(vtk, series[0])) as f:
        steps = json.load(f)["files"]
    out = os.path.join(work, "granulab")
    r = subprocess.run([binary, "run", os.path.join(root, "examples/levitation/ball.toml"), "--set",
                        f'fluid.fields=["{vtk}"]', "--out", out, "--overwrite", "--quiet"], capture_output=True, text=True)
    if r.returncode != 0:
        fail("granulab run failed:\n" + r.stdout + r.stderr)
    with open(os.path.join(out, "summary.json")) as f:
        fluid = json.load(f)["fluid"]
    print("summary.json fluid:", fluid)
    if fluid["fields"] != len(steps):
        fail(f"granulab knows {fluid['fields']} fields, foamToVTK wrote {len(steps)} time steps")
    if fluid["field_loads"] != len(steps):
        fail(f"granulab loaded {fluid['field_loads']} fields during the run, expected each of {len(steps)} once")
    with open(os.path.join(out, "series.csv")) as f:
        rows = list(csv.DictReader(f))
    if int(float(rows[-1]["fluid_field"])) != len(steps) - 1:
        fail(f"the last series row uses field {rows[-1]['fluid_field']}, expected {len(steps) - 1}")
    if any(int(float(row["fluid_outside"])) for row in rows):
        fail("the ball left the flow field")
    with open(os.path.join(out, "final.csv")) as f:
        ball = next(csv.DictReader(f))
    radius, rho_p, rho_f, cw, g = float(ball["radius"]), 15.0, 1.25, 0.47, 9.81
    terminal = math.sqrt(8.0 / 3.0 * radius * g * (rho_p - rho_f) / (rho_f * cw))
    relative = float(ball["fluid_uy"]) - float(ball["vy"])
    print(f"air at the ball {float(ball['fluid_uy']):.5f} m/s, ball {float(ball['vy']):.5f} m/s, relative "
          f"{relative:.5f} m/s, drag law {terminal:.5f} m/s ({100 * (relative / terminal - 1):+.3f} %)")
    if abs(relative / terminal - 1) > 0.01:
        fail("the ball's speed relative to the air is not the terminal speed of the drag law within 1 %")
    print("PASS")


if __name__ == "__main__":
    main()
