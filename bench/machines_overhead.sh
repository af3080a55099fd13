#!/usr/bin/env bash
# Cost of the scene machines (issue 12) in a DEM step: a bed of 1e4 disks (d = 4 mm +-10 %,
# hooke + cundall_strack, verlet, cell_grid) on a floor of 10 vibrating tiles (convex wall
# bodies, cosine 20 Hz, W = 0.1 mm), with 10 velocity walls (plates moving sideways above the
# bed), a drop source and a region outlet, run for STEPS steps. Prints the stage timers of
# summary.json (timers_s: predict, neighbors, forces, correct, updaters) and the updaters' share
# of the step time (the sum of the five). See bench/README.md, "Scene machines (issue 12)".
#
# Usage: bench/machines_overhead.sh [-s STEPS] [-k]
#   -s STEPS  steps (default 10000, dt = 8e-6 s: the bed falls 0.08 s and lands on the tiles)
#   -k        keep the work directory
# Env: THREADS (granulab threads, default 1), GRANULAB (default <repo>/build/granulab).
set -euo pipefail
THREADS=${THREADS:-1}  # granulab threads (run.threads); 1: the serial kernel

STEPS=10000 KEEP=0
while getopts "s:kh" opt; do
    case $opt in
        s) STEPS=$OPTARG ;;
        k) KEEP=1 ;;
        *) sed -n '2,13p' "$0"; exit 0 ;;
    esac
done
ROOT=$(cd "$(dirname "$0")/.." && pwd)
GRANULAB=${GRANULAB:-$ROOT/build/granulab}
WORK=$(mktemp -d)
[ "$KEEP" = 1 ] && echo "work directory: $WORK" || trap 'rm -rf "$WORK"' EXIT

python3 - "$WORK/scene.toml" "$STEPS" <<'PY'
import sys
path, steps = sys.argv[1], int(sys.argv[2])
dt = 8e-6
L = 0.6
out = [f'''[run]
title = "machines overhead: 1e4 disks, 20 moving walls, a source, an outlet"
seed = 12
end_time = {steps * dt!r}

[dem]
dt = {dt!r}
gravity = [0.0, -9.81]

[[material]]
name = "glass"
density = 12.5
[[material]]
name = "steel"

[[contact]]
materials = ["*", "*"]
normal = "hooke"
kn = 4.0e3
damping = "restitution"
e = 0.5
tangential = "cundall_strack"
mu = 0.5

[[block]]
lattice = "hexagonal"
spacing = 4.5e-3
count = 10000
region = [0.003, 0.003, {L - 0.003!r}, 0.4]
radius = {{ distribution = "uniform", min = 0.0018, max = 0.0022 }}
material = "glass"

[[wall]]
name = "sides"
points = [[0.0, 0.8], [0.0, -0.02], [0.0, -0.02], [{L!r}, -0.02], [{L!r}, 0.8]]
material = "steel"
''']
# the polyline above must not repeat a point: rewrite it without the duplicate
out[0] = out[0].replace("[0.0, -0.02], [0.0, -0.02],", "[0.0, -0.02],")
w = L / 10
for i in range(10):  # 10 vibrating floor tiles
    x0, x1 = i * w, (i + 1) * w
    out.append(f'''[[wall]]
name = "tile{i}"
kind = "polygon"
points = [[{x0!r}, -0.01], [{x1!r}, -0.01], [{x1!r}, 0.0], [{x0!r}, 0.0]]
closed = true
material = "steel"
vib_type = "cosine"
vib_frequency = 20.0
vib_width = 1.0e-4
vib_direction = 1.5707963267948966
''')
for i in range(10):  # 10 velocity walls: plates above the bed moving sideways
    x0 = 0.02 + i * w
    out.append(f'''[[wall]]
name = "plate{i}"
kind = "polygon"
points = [[{x0!r}, 0.6], [{x0 + 0.03!r}, 0.6], [{x0 + 0.03!r}, 0.605], [{x0!r}, 0.605]]
closed = true
material = "steel"
velocity = [0.01, 0.0]
''')
out.append(f'''[[source]]
material = "glass"
radius = {{ distribution = "uniform", min = 0.0018, max = 0.0022 }}
position = [{L / 2!r}, 0.55]
width = 0.2
interval = 1.0e-3
from = 0.0
to = 10.0

[[outlet]]
name = "sink"
region = [-1.0, -1.0, 2.0, -0.05]

[output]
vtk = false
''')
open(path, "w").write("\n".join(out))
PY

"$GRANULAB" run --threads "$THREADS" "$WORK/scene.toml" --out "$WORK/out" --overwrite -q
python3 - "$WORK/out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t = s["timers_s"]
stages = ["predict", "neighbors", "forces", "correct", "updaters"]
total = sum(t[k] for k in stages)
print(f"particles {s['particles']}, steps {s['steps']}, walls {len(s['wall_forces'])}, "
      f"inserted {s['flow']['inserted']}, removed {s['flow']['removed']}, "
      f"neighbor builds {s['neighbor_builds']}, loop {s['loop_time_s']:.2f} s")
for k in stages:
    print(f"  {k:<10} {t[k]:8.3f} s  {100 * t[k] / total:5.1f} %")
print(f"  {'output':<10} {t.get('output', 0.0):8.3f} s  (not in the step total)")
print(f"step total {total:.3f} s; updaters' share {100 * t['updaters'] / total:.1f} %; "
      f"{1e9 * total / (s['steps'] * s['particles']):.1f} ns per particle-step")
PY
