#!/usr/bin/env bash
# Targets of issue 13 end to end: (1) the cost of writing the contact files in a run with a
# snapshot every 1 % of the run (the disk-bed workload of examples/bench/disk_bed.toml, 1e4 disks,
# 72,000 steps, 100 snapshots): wall time with output.contacts = true against false, median of
# REPEAT runs each, alternating; (2) `granulab analyze` (stress, packing, coordination) and
# `granulab render --png --forces` of one snapshot of 1e5 disks in contact (a hexagonal bed of
# touching disks compressed by gravity for 1000 steps). See bench/README.md "Analysis (issue 13)".
#
# Usage: bench/contacts_overhead.sh [-r REPEAT] [-k]
# Env: THREADS (granulab threads, default 1), GRANULAB (default <repo>/build/granulab).
set -euo pipefail
THREADS=${THREADS:-1}  # granulab threads (run.threads); 1: the serial kernel

REPEAT=1 KEEP=0
while getopts "r:kh" opt; do
    case $opt in
        r) REPEAT=$OPTARG ;;
        k) KEEP=1 ;;
        *) sed -n '2,10p' "$0"; exit 0 ;;
    esac
done
ROOT=$(cd "$(dirname "$0")/.." && pwd)
GRANULAB=${GRANULAB:-$ROOT/build/granulab}
WORK=$(mktemp -d)
[ "$KEEP" = 1 ] && echo "work directory: $WORK" || trap 'rm -rf "$WORK"' EXIT
cd "$WORK"

seconds() { python3 -c 'import sys, json; print(json.load(open(sys.argv[1]))["wall_time_s"])' "$1/summary.json"; }
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

# (1) The whole workload (72,000 steps, 1e4 disks, settling then settled) with a snapshot every
# 1 % of the run (720 steps), with and without contact files; the stage timers show where the
# difference goes (output: writing; forces: recording on the 100 snapshot steps).
BED="$ROOT/examples/bench/disk_bed.toml"
on=() off=()
for k in $(seq "$REPEAT"); do
    for contacts in true false; do
        rm -rf "run_$contacts"
        "$GRANULAB" run --threads "$THREADS" "$BED" --out "run_$contacts" -q --set output.snapshot_interval=0.072 \
            --set output.contacts=$contacts > /dev/null
        t=$(seconds "run_$contacts")
        [ "$contacts" = true ] && on+=("$t") || off+=("$t")
    done
done
ON=$(printf '%s\n' "${on[@]}" | median) OFF=$(printf '%s\n' "${off[@]}" | median)
echo "contact files, disk-bed workload (1e4 disks, 72,000 steps, 100 snapshots): with ${ON} s," \
     "without ${OFF} s (median of $REPEAT): overhead $(python3 -c "print(f'{100 * ($ON / $OFF - 1):.1f} %')")"
for contacts in true false; do
    python3 -c 'import sys, json; t = json.load(open(sys.argv[1]))["timers_s"]; print(sys.argv[2], "timers [s]:", {k: round(v, 2) for k, v in t.items()})' \
        "run_$contacts/summary.json" "contacts=$contacts"
done

# (2) 1e5 disks (316 x 316) in contact: touching hexagonal bed compressed by gravity.
"$GRANULAB" run --threads "$THREADS" "$BED" --out big -q --set run.end_time=0.1 --set run.benchmark_from=-1 \
    --set 'block[0].region=[0.1,0.0,354.0,307.0]' --set 'block[0].radius={distribution="uniform",min=0.55,max=0.56}' \
    --set 'wall[0].points=[[0.0,400.0],[0.0,0.0],[355.0,0.0],[355.0,400.0]]' --set 'dem.damping=[]' \
    --set output.snapshot_interval=0.1 > /dev/null
python3 - big <<'PY'
import sys, json
s = json.load(open(sys.argv[1] + "/summary.json"))
print(f"1e5-disk snapshot: {s['particles']} grains")
PY
for k in 1 2 3; do /usr/bin/time -f "analyze stress packing coordination: %e s wall, %U s user" \
    "$GRANULAB" analyze big stress packing coordination -q; done
if "$GRANULAB" render --help | grep -q -- --forces; then
    for k in 1 2 3; do /usr/bin/time -f "render --png --forces (2 frames): %e s wall, %U s user" \
        "$GRANULAB" render big --png --forces -q; done
fi
