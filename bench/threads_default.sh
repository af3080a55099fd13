#!/usr/bin/env bash
# The default thread count against the best fixed one (issue 33; docs/physics/dem-threads.md, "How
# the default is chosen"). For disks and gc2d 7-gons at several grain counts, three runs of the
# same scene and steps: --threads 1, --threads <all cores>, and the default (no --threads: the
# automatic count); first on the machine as it is (run it idle), then with one competing busy
# process per core, which the script starts and stops itself. Speed = particle-steps per second
# of the run loop (summary.json); the default's cell is judged against the best cell of its row
# (target >= 0.9x). A run that keeps on far past the time the 1-thread run took is stopped with
# SIGINT (granulab writes its summary at the step it reached), so a collapsing run on busy cores
# costs seconds, not minutes.
#   disks   examples/bench/disk_bed.toml (hooke, verlet, cell grid): N disks on the hexagonal
#           lattice of spacing 1.12, falling into a box of the lattice's width
#   7-gons  examples/bench/polygon_pile_10k.toml (gc2d area law, gear, sort-and-sweep): N grains on
#           its lattice (spacing 3.6 mm), falling into a box of the lattice's width
# Steps: about 4e7 particle-steps per disk run and 3.2e7 per polygon run (at least 200 steps), so
# that a run lasts a second or more: on busy cores runs of a third of a second differed by 15 %
# between identical repeats (the "spread" column: (max - min) / median of the 1-thread repeats).
#
# Usage: bench/threads_default.sh [-N "100 512 2000 10000 100000"] [-s "disk 7gon"] [-r R] [-l "idle busy"] [-c CORES]
#   -N  grain counts      -s  shapes      -r  repeats per cell (median; default 1)
#   -l  loads: idle (the machine as it is), busy (one busy loop per core)
#   -c  the "all cores" thread count (default: nproc)
# Env: GRANULAB (default <repo>/build/granulab), RESULTS_DIR (default <repo>/bench/results/<hostname>).
set -euo pipefail
SIZES="100 512 2000 10000 100000" SHAPES="disk 7gon" REPEATS=1 LOADS="idle busy" CORES=$(nproc)
while getopts "N:s:r:l:c:h" opt; do
    case $opt in
        N) SIZES=$OPTARG ;;
        s) SHAPES=$OPTARG ;;
        r) REPEATS=$OPTARG ;;
        l) LOADS=$OPTARG ;;
        c) CORES=$OPTARG ;;
        h) sed -n '2,22p' "$0"; exit 0 ;;
        *) sed -n '2,22p' "$0" >&2; exit 2 ;;
    esac
done
ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
GRANULAB=${GRANULAB:-"$ROOT/build/granulab"}
HOST=$(hostname)
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$HOST"}
[[ -x $GRANULAB ]] || { echo "error: granulab binary not found: $GRANULAB (scripts/setup.sh, or set GRANULAB)" >&2; exit 1; }
if busy=$(pgrep -af 'granulab_tests|granulab run|lmp -in|cc1plus' 2>/dev/null) && [[ -n $busy ]]; then
    echo "warning: other jobs are running; the idle rows are not idle:" >&2
    echo "$busy" | cut -c1-120 >&2
fi
WORK=$(mktemp -d "${TMPDIR:-/tmp}/threads_default.XXXXXX")
HOGS=()
cleanup() {
    ((${#HOGS[@]})) && kill "${HOGS[@]}" 2>/dev/null || true
    rm -rf "$WORK"
}
trap cleanup EXIT

# The --set overrides of one scene: N grains on the scene's lattice in a box as wide as the lattice.
overrides() {  # shape N steps
    python3 - "$1" "$2" "$3" <<'EOF'
import math, sys
shape, n, steps = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
nx = max(4, math.ceil(math.sqrt(n)))
rows = math.ceil(n / nx) + 1
if shape == "disk":
    s, dt, dy = 1.12, 1e-4, 1.12 * math.sqrt(3) / 2
    x0 = 0.1
else:
    s, dt, dy = 3.6e-3, 2e-6, 3.6e-3 * math.sqrt(3) / 2
    x0 = s / 2
w = nx * s + s / 2
top = (rows + 2) * dy + 3 * s
sets = [f"block[0].count={n}", f"block[0].region=[{x0:.6g},0,{nx * s + x0 / 2:.6g},{top:.6g}]",
        f"wall[0].points=[[0,{2 * top:.6g}],[0,0],[{w:.6g},0],[{w:.6g},{2 * top:.6g}]]",
        f"run.end_time={steps * dt:.10g}", "run.benchmark_from=0", f"output.series_interval={steps * dt:.10g}",
        f"output.checkpoint_interval={steps * dt:.10g}", "output.vtk=false", "dem.damping[0].gamma=0"]
print(" ".join("--set " + x for x in sets))
EOF
}

# One run; prints "speed threads reason" (speed in particle-steps/s of the loop).
run_one() {  # scene N sets threads(empty: default) limit_s out
    local scene=$1 n=$2 sets=$3 threads=$4 limit=$5 out=$6 targs=()
    [[ -n $threads ]] && targs=(--threads "$threads")
    # shellcheck disable=SC2086
    timeout -s INT "$limit" "$GRANULAB" run "$scene" $sets "${targs[@]}" --out "$out" --overwrite --quiet \
        >/dev/null 2>"$out.log" || true
    python3 - "$out/summary.json" <<'EOF'
import json, sys
try:
    s = json.load(open(sys.argv[1]))
except Exception:
    print("0 0 no-summary"); sys.exit()
c = s.get("threads_choice", {})
print(f"{s['particle_steps_per_s']:.6g} {s['threads']} {c.get('reason', '').replace(' ', '_')}")
EOF
}

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

mkdir -p "$RESULTS_DIR"
CSV="$RESULTS_DIR/threads_default.csv"
[[ -f $CSV ]] || echo "date,host,load,shape,N,steps,one,all,default,default_threads,default_over_best,reason,one_spread" >"$CSV"
# A file of the first version lacks the last column: name it (its old rows leave it empty).
head -1 "$CSV" | grep -q ',one_spread$' || sed -i '1s/$/,one_spread/' "$CSV"
echo "granulab $("$GRANULAB" --version 2>/dev/null | head -1), $CORES cores for 'all', repeats $REPEATS; particle-steps/s of the run loop"
FAIL=0
for load in $LOADS; do
    HOGS=()
    if [[ $load == busy ]]; then
        for ((c = 0; c < $(nproc); ++c)); do (while :; do :; done) & HOGS+=($!); done
        sleep 1
    fi
    echo
    echo "load: $load$([[ $load == busy ]] && echo " (one busy loop per core: ${#HOGS[@]})")"
    printf '  %-6s %7s %7s | %10s %10s %10s | %8s %7s %6s  %s\n' shape N steps "1 thread" "$CORES thr" default "def/best" "threads" "spread" "why (default)"
    for shape in $SHAPES; do
        scene="$ROOT/examples/bench/disk_bed.toml" budget=40000000
        [[ $shape == 7gon ]] && scene="$ROOT/examples/bench/polygon_pile_10k.toml" budget=32000000
        for n in $SIZES; do
            steps=$((budget / n)); ((steps < 200)) && steps=200
            sets=$(overrides "$shape" "$n" "$steps")
            ones=() alls=() defs=() dthr="" why=""
            limit=600  # set from the first 1-thread run of the cell (the first repeat starts with it)
            for ((r = 0; r < REPEATS; ++r)); do
                # The three runs in a rotating order (one-all-default, all-default-one, default-one-all):
                # on a loaded machine no cell always runs right after the slowest one.
                s1="" sa="" sd=""
                for ((k = 0; k < 3; ++k)); do
                    case $(((r + k) % 3)) in
                        0) t0=$(date +%s.%N)
                           read -r s1 _ _ < <(run_one "$scene" "$n" "$sets" 1 "$limit" "$WORK/one")
                           [[ $limit == 600 ]] && limit=$(python3 -c "print(max(5, round(3 * ($(date +%s.%N) - $t0) + 2)))") ;;
                        1) read -r sa _ _ < <(run_one "$scene" "$n" "$sets" "$CORES" "$limit" "$WORK/all") ;;
                        2) read -r sd dthr why < <(run_one "$scene" "$n" "$sets" "" "$limit" "$WORK/def") ;;
                    esac
                done
                ones+=("$s1") alls+=("$sa") defs+=("$sd")
            done
            m1=$(median "${ones[@]}") ma=$(median "${alls[@]}") md=$(median "${defs[@]}")
            ratio=$(python3 -c "b = max($m1, $ma); print(f'{$md / b:.2f}' if b > 0 else '0')")
            # Spread of the 1-thread repeats, (max - min) / median: the noise of one cell on this
            # machine under this load (the default runs one thread below the threaded size, so there
            # the def/best ratio differs from 1 by noise alone).
            spread=$(python3 -c "v = [$(IFS=,; echo "${ones[*]}")]; m = $m1; print(f'{(max(v) - min(v)) / m:.2f}' if m > 0 else '0')")
            ok=$(python3 -c "print('ok' if $ratio >= 0.9 else 'LOW')")
            [[ $ok == ok ]] || FAIL=1
            printf '  %-6s %7d %7d | %10.3g %10.3g %10.3g | %5s %-3s %4s %9s  %s\n' "$shape" "$n" "$steps" "$m1" "$ma" "$md" "$ratio" "$ok" "$dthr" "$spread" "${why//_/ }"
            echo "$(date -Iseconds),$HOST,$load,$shape,$n,$steps,$m1,$ma,$md,$dthr,$ratio,\"${why//_/ }\",$spread" >>"$CSV"
        done
    done
    if ((${#HOGS[@]})); then kill "${HOGS[@]}" 2>/dev/null || true; wait "${HOGS[@]}" 2>/dev/null || true; HOGS=(); fi
done
echo
echo "appended to $CSV"
[[ $FAIL == 0 ]] && echo "every default cell >= 0.9x the best cell of its row" || echo "some default cells below 0.9x the best of their row (LOW)"
