#!/usr/bin/env bash
# Event-driven engine against N (issue 5 target: events per second flat within 30 % from 1e4 to
# 1e7 particles, at most 120 bytes per particle): elastic hard spheres (3D) or disks (2D) at
# volume fraction NU in a periodic box, started on a lattice, EQUIL elastic collisions per
# particle, then COLL collisions per particle timed (at least 2e6 collisions in all). Prints
# events/s, collisions/s, engine bytes per particle and peak RSS per particle from summary.json,
# and writes them to RESULTS_DIR/edmd_scaling_<D>d.csv.
#
# Usage: bench/edmd_scaling.sh [-d 3] [-N "10000 100000 1000000 10000000"] [-n 0.25] [-c 10] [-e 5]
# Env: GRANULAB (binary; default <repo>/build/granulab), RESULTS_DIR (default
#      <repo>/bench/results/<hostname>).
set -euo pipefail

DIM=3 SIZES="10000 100000 1000000 10000000" NU=0.25 COLL=10 EQUIL=5
while getopts "d:N:n:c:e:h" opt; do
    case $opt in
        d) DIM=$OPTARG ;;
        N) SIZES=$OPTARG ;;
        n) NU=$OPTARG ;;
        c) COLL=$OPTARG ;;
        e) EQUIL=$OPTARG ;;
        h) sed -n '2,11p' "$0"; exit 0 ;;
        *) sed -n '2,11p' "$0" >&2; exit 2 ;;
    esac
done
[[ $DIM == 2 || $DIM == 3 ]] || { echo "error: -d must be 2 or 3" >&2; exit 2; }

ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
GRANULAB=${GRANULAB:-"$ROOT/build/granulab"}
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$(hostname)"}
mkdir -p "$RESULTS_DIR"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cat > "$WORK/gas.toml" <<TOML
[run]
engine = "edmd"
dimension = $DIM
seed = 7
[edmd]
count = 1000
volume_fraction = $NU
radius = 0.5
series_points = 2
clusters = false
analysis_files = false
[output]
vtk = false
TOML
OUT="$RESULTS_DIR/edmd_scaling_${DIM}d.csv"
echo "dimension,particles,volume_fraction,collisions,events_per_s,collisions_per_s,bytes_per_particle,peak_rss_per_particle" > "$OUT"
printf "%10s %14s %16s %12s %12s\n" N events/s collisions/s "B/particle" "RSS B/p"
for N in $SIZES; do
    # at least 2e6 timed collisions: raise the per-particle count for small N
    per=$(python3 -c "print(max($COLL, 4e6 / $N))")
    "$GRANULAB" run "$WORK/gas.toml" --out "$WORK/out" --overwrite -q --set edmd.count="$N" --set edmd.equilibrate="$EQUIL" \
        --set edmd.end_collisions="$per" >/dev/null
    python3 - "$WORK/out/summary.json" "$OUT" "$DIM" "$NU" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
n = s["particles"]
row = [sys.argv[3], n, sys.argv[4], s["collisions"], s["events_per_s"], s["collisions_per_s"], s["bytes_per_particle"],
       s["peak_rss_bytes"] / n]
open(sys.argv[2], "a").write(",".join(str(v) for v in row) + "\n")
print(f"{n:10d} {s['events_per_s']:14.4g} {s['collisions_per_s']:16.4g} {s['bytes_per_particle']:12.1f} {s['peak_rss_bytes'] / n:12.1f}")
PY
done
echo "written to $OUT"
