#!/usr/bin/env bash
# Event-driven engine against cells per particle C/N (edmd spec 2.4, Fig. 2.3, acceptance test
# AT-6: a broad minimum of CPU time per collision near C/N ~ 1.5 in 2D and ~8 in 3D at low
# density; at high density the cells cannot shrink below a diameter). Elastic hard disks (2D)
# and spheres (3D), N particles in a periodic box at a low and a moderate volume fraction,
# started on a lattice, EQUIL elastic collisions per particle, then the fraction's collisions
# per particle timed (NU:COLL in the -2/-3 lists: a dilute gas makes ~10 (2D) to ~140 (3D) cell
# crossings per collision, so it runs fewer), for each edmd.cells_per_particle in the list with
# edmd.cell_grid = GRID. Prints dimension, volume fraction, C/N requested, the cells per axis
# and C/N the engine used, and collisions/s from summary.json; writes them to
# RESULTS_DIR/edmd_cells_sweep.csv.
#
# Usage: bench/edmd_cells_sweep.sh [-N 10000] [-C "0.5 1 1.5 2 4 8 16 32"] [-e 1] [-g free]
#            [-2 "0.008:100 0.2:1000"] [-3 "0.0005:20 0.1:1000"]
# Env: GRANULAB (binary; default <repo>/build/granulab), RESULTS_DIR (default
#      <repo>/bench/results/<hostname>).
set -euo pipefail

N=10000 RATIOS="0.5 1 1.5 2 4 8 16 32" EQUIL=1 GRID=free
FRACTIONS_2D="0.008:100 0.2:1000"  # spec Fig. 2.3 low density (2D: nu = 0.008) and a moderate one
FRACTIONS_3D="0.0005:20 0.1:1000"  # spec Fig. 2.3 low density (3D: nu = 0.0005) and a moderate one
while getopts "N:C:e:g:2:3:h" opt; do
    case $opt in
        N) N=$OPTARG ;;
        C) RATIOS=$OPTARG ;;
        e) EQUIL=$OPTARG ;;
        g) GRID=$OPTARG ;;
        2) FRACTIONS_2D=$OPTARG ;;
        3) FRACTIONS_3D=$OPTARG ;;
        h) sed -n '2,16p' "$0"; exit 0 ;;
        *) sed -n '2,16p' "$0" >&2; exit 2 ;;
    esac
done
[[ $GRID == free || $GRID == morton ]] || { echo "error: -g must be free or morton" >&2; exit 2; }

ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
GRANULAB=${GRANULAB:-"$ROOT/build/granulab"}
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$(hostname)"}
mkdir -p "$RESULTS_DIR"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
OUT="$RESULTS_DIR/edmd_cells_sweep.csv"
echo "dimension,particles,volume_fraction,cell_grid,cells_per_particle_requested,cells_per_axis,cells_per_particle,collisions,collisions_per_s,wall_time_s" > "$OUT"
printf "%3s %8s %8s %14s %8s %14s\n" D nu "C/N asked" "cells/axis" "C/N" collisions/s
for DIM in 2 3; do
    FRACTIONS=$FRACTIONS_2D
    [[ $DIM == 3 ]] && FRACTIONS=$FRACTIONS_3D
    cat > "$WORK/gas.toml" <<TOML
[run]
engine = "edmd"
dimension = $DIM
seed = 11
[edmd]
count = $N
volume_fraction = 0.1
radius = 0.5
series_points = 2
clusters = false
analysis_files = false
[output]
vtk = false
TOML
    for CASE in $FRACTIONS; do
        NU=${CASE%%:*} COLL=${CASE#*:}
        [[ $CASE == *:* ]] || COLL=20
        for RATIO in $RATIOS; do
            "$GRANULAB" run "$WORK/gas.toml" --out "$WORK/out" --overwrite -q --set edmd.volume_fraction="$NU" \
                --set edmd.cells_per_particle="$RATIO" --set edmd.cell_grid="$GRID" \
                --set edmd.equilibrate="$EQUIL" --set edmd.end_collisions="$COLL" >/dev/null
            python3 - "$WORK/out/summary.json" "$OUT" "$DIM" "$NU" "$GRID" "$RATIO" <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1]))
n = s["particles"]
cells = s["cells_per_axis"]
cn = math.prod(cells) / n
row = [sys.argv[3], n, sys.argv[4], sys.argv[5], sys.argv[6], "x".join(map(str, cells)), f"{cn:.4g}",
       s["collisions"], s["collisions_per_s"], s["wall_time_s"]]
open(sys.argv[2], "a").write(",".join(str(v) for v in row) + "\n")
print(f"{sys.argv[3]:>3} {sys.argv[4]:>8} {sys.argv[6]:>8} {'x'.join(map(str, cells)):>14} {cn:8.3g} "
      f"{s['collisions_per_s']:14.4g}")
PY
        done
    done
done
echo "written to $OUT"
