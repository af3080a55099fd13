#!/usr/bin/env bash
# Evidence for the contact-law calibration of examples/bench/squares_512.toml: the face-to-face
# normal stiffness of two squares, in LAMMPS (pair body/rounded/polygon, k_n = 100, as in
# ../shared/peers/in.squares_pile.lmp) and in granulab (gc2d area law, E and cohesion of the scene).
# LAMMPS: a mobile rounded square (core edge 4, rounding diameter 0.5, mass 1) rests on a frozen one,
# shifted sideways by DX; the overlaps of its two lowest vertices give F / overlap (mean overlap).
# granulab: two sharp squares of edge 4.5 stacked on the floor wall; F / overlap from the centres.
# Runs a few seconds. Usage: bench/squares_calibration.sh   (env: GRANULAB, LMP)
set -euo pipefail
THREADS=${THREADS:-1}  # granulab threads (run.threads); 1: the serial kernel
ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
GRANULAB=${GRANULAB:-"$ROOT/build/granulab"}
LMP=${LMP:-lmp}
SCENE="$ROOT/examples/bench/squares_512.toml"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/squares_calibration.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

for kna in 0 2; do for dx in 0 0.5 1.0; do for g in 0.3 1.0; do
    d="$WORK/l_${kna}_${dx}_$g"; mkdir -p "$d"
    python3 - "$d/data.two_squares" "$dx" <<'PY'
import sys
path, dx = sys.argv[1], float(sys.argv[2])
with open(path, "w") as f:
    f.write("two squares\n2 atoms\n2 bodies\n1 atom types\n0 12 xlo xhi\n0 40 ylo yhi\n-0.5 0.5 zlo zhi\n\nAtoms\n\n")
    f.write(f"1 1 1 1 6.0 3.0 0\n2 1 1 1 {6.0 + dx} 7.55 0\n\nBodies\n\n")
    for k in (1, 2):
        f.write(f"{k} 1 19\n4\n1 1 2.67 0 0 0\n-2 -2 0\n-2 2 0\n2 2 0\n2 -2 0\n0.5\n")
PY
    (cd "$d" && "$LMP" -in "$ROOT/bench/lammps/two_squares.lmp" -var g "$g" -var kna "$kna" \
        -var dumpfile verts.dump -log log.lammps -screen none) || { echo "error: LAMMPS failed in $d" >&2; exit 1; }
    python3 - "$d/verts.dump" "$g" "$dx" "$kna" >> "$WORK/lammps.txt" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("ITEM: ENTRIES")[-1].strip().splitlines()[1:]
rows = [list(map(float, l.split()[1:])) for l in lines]          # id x y
low = sorted((r for r in rows if r[0] == 2), key=lambda r: r[2])[:2]
o = [5.5 - r[2] for r in low]     # frozen top face vertices at y = 5, contact at 0.25 + 0.25
g = float(sys.argv[2])
print(sys.argv[4], sys.argv[3], g, o[0], o[1])
PY
done; done; done

read -r E COH < <(python3 -c "
import tomllib; c = tomllib.load(open('$SCENE', 'rb'))['contact'][0]; print(c['E'], c.get('cohesion', 0.0))")
for coh in 0 "$COH"; do for g in 0.3 1.0 3.0; do
    d="$WORK/g_${coh}_$g"
    cat > "$WORK/two.toml" <<TOML
[run]
end_time = 40.0
[dem]
dt = 0.001
gravity = [0.0, -$g]
[[material]]
name = "grain"
density = 0.04938271604938271
[[material]]
name = "floor"
[[shape]]
name = "sq"
kind = "rectangle"
size = [4.5, 4.5]
[[contact]]
materials = ["*", "*"]
normal = "area"
E = $E
cohesion = $coh
damping = "gamma"
gamma = 0.5
tangential = "gc2d"
mu = 0.3
[[particle]]
shape = "sq"
position = [6.0, 2.25]
material = "grain"
[[particle]]
shape = "sq"
position = [6.0, 6.75]
material = "grain"
[[wall]]
points = [[0.0, 0.0], [12.0, 0.0]]
material = "floor"
[output]
vtk = false
TOML
    "$GRANULAB" run --threads "$THREADS" "$WORK/two.toml" --out "$d" --quiet || { echo "error: granulab failed ($d)" >&2; exit 1; }
    python3 - "$d/final.csv" "$g" "$coh" >> "$WORK/granulab.txt" <<'PY'
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))
h = 4.5 - (float(r[1]["y"]) - float(r[0]["y"]))
g = float(sys.argv[2])
print(sys.argv[3], g, h)
PY
done; done

python3 - "$WORK/lammps.txt" "$WORK/granulab.txt" "$E" "$COH" "$(basename "$SCENE")" <<'PY'
import sys
L = [l.split() for l in open(sys.argv[1])]
G = [l.split() for l in open(sys.argv[2])]
E, coh, scene = float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
print("LAMMPS pair body/rounded/polygon (k_n = 100, delta_ua = 0.5, mu = 0.3, cut_inner = 0.5); a mobile square")
print("(mass 1) on a frozen one, shifted sideways by DX; overlap = mean of its two lowest vertices")
print(f"  {'DX':>4} {'g':>5} {'overlap, k_na=0':>16} {'stiffness g/overlap':>20} {'overlap, k_na=2':>16} {'attraction':>11}")
k0 = {}
for kna, dx, g, o1, o2 in L:
    o = 0.5 * (float(o1) + float(o2))
    if kna == "0": k0[(dx, g)] = (o, float(g) / o)
for kna, dx, g, o1, o2 in L:
    if kna != "2": continue
    o = 0.5 * (float(o1) + float(o2)); o0, k = k0[(dx, g)]
    print(f"  {float(dx):>4} {float(g):>5} {o0:>16.6f} {k:>20.1f} {o:>16.6f} {k * o - float(g):>11.2f}")
print(f"granulab, grain/grain law of {scene} (E = {E:g}, 4 E = {4 * E:g}): two sharp squares of edge 4.5 (mass 1)")
print("stacked on the floor wall, aligned; overlap from the centres")
print(f"  {'g':>5} {'overlap, cohesion=0':>20} {'stiffness g/overlap':>20} {f'overlap, cohesion={coh:g}':>22} {'attraction':>11}")
g0 = {g: float(h) for c, g, h in G if float(c) == 0}
for c, g, h in G:
    if float(c) == 0: continue
    k = float(g) / g0[g]
    print(f"  {float(g):>5} {g0[g]:>20.6e} {k:>20.1f} {float(h):>22.6e} {k * float(h) - float(g):>11.2f}")
PY
