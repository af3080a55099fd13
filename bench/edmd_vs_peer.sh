#!/usr/bin/env bash
# The event-driven kernel against the fastest published single-core code (issue 15): F.
# Smallenburg's "Single" event-driven MD (EPJE 45, 22 (2022); public source
# https://github.com/FSmallenburg/EDMD, directory Single/), on 32,000 elastic hard spheres in a
# periodic cube at each volume fraction of the list (granulab: examples/bench/spheres_32k_0XX.toml).
# Both start from a lattice and are equilibrated (granulab: 100 collisions per particle; the peer:
# TEQ time units, ~2e6 collisions), then COLL collisions are timed by each code's own clock around
# its event loop only. Runs alternate (granulab, peer) PAIRS times per fraction; the script prints
# every pair, the medians and the median of the per-pair ratios, and writes
# RESULTS_DIR/edmd_vs_peer.csv.
#
# The peer is built outside the repository from PEER_SRC (a checkout of that repository) with its
# Makefile's flags (gcc -Ofast -funroll-loops -march=native). Its parameters are set by editing a
# copy of mdSingle.c: FCC start (N = 32,000 = 4 * 20^3), packing fraction, no thermostat, the run
# length, and its three tuning knobs: shell size (neighbour lists; default 1.5), event-list time
# multiplier (default 1) and schedule horizon (default 1.0). PEER_TUNED=1 uses the best values
# found on the reference VM (shell 1.3 at nu <= 0.35, else 1.5; multiplier 10; horizon 5): the
# peer's published defaults are slower here, by up to 30 % at nu = 0.30.
#
# Usage: bench/edmd_vs_peer.sh [-f "0.45 0.30"] [-p 5] [-c 1e7] [-e 5]
# Env: PEER_SRC (required), PEER_TUNED (0 or 1, default 1), GRANULAB (default
#      <repo>/build/granulab), RESULTS_DIR (default <repo>/bench/results/<hostname>), CC (gcc).
set -euo pipefail

FRACTIONS="0.45 0.30" PAIRS=5 COLL=1e7 TEQ=5
while getopts "f:p:c:e:h" opt; do
    case $opt in
        f) FRACTIONS=$OPTARG ;;
        p) PAIRS=$OPTARG ;;
        c) COLL=$OPTARG ;;
        e) TEQ=$OPTARG ;;
        h) sed -n '2,23p' "$0"; exit 0 ;;
        *) sed -n '2,23p' "$0" >&2; exit 2 ;;
    esac
done
[[ -n ${PEER_SRC:-} && -f $PEER_SRC/Single/mdSingle.c ]] || {
    echo "error: set PEER_SRC to a checkout of https://github.com/FSmallenburg/EDMD (Single/mdSingle.c missing)" >&2
    exit 2
}
ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
GRANULAB=${GRANULAB:-"$ROOT/build/granulab"}
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$(hostname)"}
PEER_TUNED=${PEER_TUNED:-1}
CC=${CC:-gcc}
mkdir -p "$RESULTS_DIR"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# build_peer FRACTION T_END OUT: a copy of mdSingle.c with this workload's parameters, compiled.
build_peer() {
    local fraction=$1 tend=$2 out=$3 shell=1.5 mult=1 horizon=1.0
    if [[ $PEER_TUNED == 1 ]]; then
        mult=10 horizon=5
        shell=$(python3 -c "print(1.3 if $fraction <= 0.35 else 1.5)")
    fi
    local src="$WORK/src_$fraction"
    mkdir -p "$src"
    cp "$PEER_SRC"/Single/*.c "$PEER_SRC"/Single/*.h "$src/"
    python3 - "$src/mdSingle.c" "$fraction" "$TEQ" "$tend" "$shell" "$mult" "$horizon" <<'PY'
import sys
path, fraction, teq, tend, shell, mult, horizon = sys.argv[1:]
s = open(path).read()
edits = [
    ("double maxtime = 100;", f"double maxtime = {tend};"),
    ("int initialconfig = 0;", "int initialconfig = 1;"),
    ("double packfrac = 0.25;", f"double packfrac = {fraction};"),
    ("int N = 4000;", "int N = 32000;"),
    ("const int usethermostat = 1;", "const int usethermostat = 0;"),
    ("const double shellsize = 1.5;", f"const double shellsize = {shell};"),
    ("double eventlisttimemultiplier = 1;", f"double eventlisttimemultiplier = {mult};"),
    ("double maxscheduletime = 1.0;", f"double maxscheduletime = {horizon};"),
    ("int main()\n{", "#include <time.h>\nstatic double wallNow(void) { struct timespec t; "
     "clock_gettime(CLOCK_MONOTONIC, &t); return t.tv_sec + 1e-9 * t.tv_nsec; }\nint main()\n{"),
    ("    while (simtime <= maxtime)\n    {\n      step();\n    }",
     f"    while (simtime <= {teq}) step();\n"
     "    unsigned int timedFrom = colcounter; double wallFrom = wallNow();\n"
     "    while (simtime <= maxtime) step();\n"
     "    printf(\"TIMED %u %.6f\\n\", colcounter - timedFrom, wallNow() - wallFrom);"),
]
for old, new in edits:
    if old not in s:
        sys.exit(f"edmd_vs_peer.sh: the peer source changed; cannot find {old!r}")
    s = s.replace(old, new)
open(path, "w").write(s)
PY
    "$CC" -Wall -Ofast -funroll-loops -march=native "$src/mdSingle.c" -o "$out" -lm
}

# peer_rate BINARY: collisions/s of its timed segment (run in $WORK: it writes snapshots to cwd).
peer_rate() {
    (cd "$WORK" && "$1" | awk '/^TIMED/ { printf "%.6g %d\n", $2 / $3, $2 }')
}

OUT="$RESULTS_DIR/edmd_vs_peer.csv"
echo "volume_fraction,pair,granulab_collisions_per_s,peer_collisions_per_s,ratio,peer_tuned" > "$OUT"
for NU in $FRACTIONS; do
    scene="$ROOT/examples/bench/spheres_32k_0${NU#0.}.toml"
    [[ -f $scene ]] || scene="$ROOT/examples/bench/spheres_32k_045.toml"
    # Peer run length: its collision rate per unit time from a short calibration run.
    build_peer "$NU" "$((TEQ + 1))" "$WORK/calibrate"
    read -r _ calib < <(peer_rate "$WORK/calibrate")
    tend=$(python3 -c "print($TEQ + $COLL / $calib)")
    build_peer "$NU" "$tend" "$WORK/peer"
    per=$(python3 -c "print(2 * $COLL / 32000)")
    for ((k = 1; k <= PAIRS; k++)); do
        "$GRANULAB" run "$scene" --out "$WORK/g" --overwrite -q --set edmd.volume_fraction="$NU" \
            --set edmd.end_collisions="$per" >/dev/null
        ours=$(python3 -c "import json; print(json.load(open('$WORK/g/summary.json'))['collisions_per_s'])")
        read -r theirs _ < <(peer_rate "$WORK/peer")
        ratio=$(python3 -c "print(f'{$ours / $theirs:.3f}')")
        printf "nu=%s pair %d: granulab %.4g  peer %.4g  ratio %s\n" "$NU" "$k" "$ours" "$theirs" "$ratio"
        echo "$NU,$k,$ours,$theirs,$ratio,$PEER_TUNED" >> "$OUT"
    done
    python3 - "$OUT" "$NU" <<'PY'
import csv, statistics, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["volume_fraction"] == sys.argv[2]]
med = lambda k: statistics.median(float(r[k]) for r in rows)
print(f"nu={sys.argv[2]}: medians granulab {med('granulab_collisions_per_s'):.4g}, "
      f"peer {med('peer_collisions_per_s'):.4g}; median ratio {med('ratio'):.3f} "
      f"(range {min(float(r['ratio']) for r in rows):.3f}-{max(float(r['ratio']) for r in rows):.3f})")
PY
done
echo "wrote $OUT"
