#!/usr/bin/env bash
# Load balancing of the DEM domain decomposition on a heap that a drop source builds (issue 16;
# examples/bench/heap_source.toml, docs/physics/dem-mpi.md): the scene on one rank, then on P
# MPI ranks with the contact-weighted cuts (run.load_balance = true) and with the first cuts kept
# (false: equal slabs over the box). Prints the particle-steps/s of the timed segment (the last
# second, 2000-3000 grains), the parallel efficiency rate(P) / (P rate(1)), the mean work
# imbalance (busiest rank / mean, over the exchanges: 1 / imbalance bounds the efficiency
# whatever the machine) and the halo share. Appends to $RESULTS_DIR/heap_balance.csv.
#
# Usage: bench/heap_balance.sh [-P "2 4"] [-e END] [-x]
#   -P LIST   rank counts (default "2 4"; those above the cores are run oversubscribed only with -x)
#   -e END    run.end_time [s] (default 3.0; the timed segment starts at END - 1)
#   -x        allow more ranks than cores (--oversubscribe): the imbalance is still the
#             decomposition's, the timings are not
# Env: GRANULAB (default <repo>/build/granulab), RESULTS_DIR (default <repo>/bench/results/<hostname>).
set -euo pipefail
LIST="2 4" END=3.0 OVER=0
while getopts "P:e:xh" opt; do
    case $opt in
        P) LIST=$OPTARG ;;
        e) END=$OPTARG ;;
        x) OVER=1 ;;
        h) sed -n '2,17p' "$0"; exit 0 ;;
        *) sed -n '2,17p' "$0" >&2; exit 2 ;;
    esac
done
ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
GRANULAB=${GRANULAB:-"$ROOT/build/granulab"}
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$(hostname)"}
SCENE="$ROOT/examples/bench/heap_source.toml"
CORES=$(nproc)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
WORK=$(mktemp -d "${TMPDIR:-/tmp}/heap_balance.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
common=(--quiet --threads 1 --set "run.end_time=$END" --set "run.benchmark_from=$(python3 -c "print($END - 1)")"
        --set output.snapshot_interval=0 --set output.vtk=false)
echo "heap from a drop source: 1 rank ..." >&2
"$GRANULAB" run "$SCENE" --out "$WORK/r1" "${common[@]}"
for P in $LIST; do
    launch=(mpirun -np "$P" --bind-to core)
    if ((P > CORES)); then
        ((OVER == 1)) || { echo "skipping P = $P: $CORES cores (-x to oversubscribe)" >&2; continue; }
        launch=(mpirun -np "$P" --oversubscribe --bind-to none)
    fi
    for balance in true false; do
        echo "heap from a drop source: $P ranks, load_balance = $balance ..." >&2
        "${launch[@]}" "$GRANULAB" run "$SCENE" --out "$WORK/r${P}_$balance" "${common[@]}" \
            --set "run.load_balance=$balance"
    done
done
mkdir -p "$RESULTS_DIR"
python3 - "$WORK" "$RESULTS_DIR/heap_balance.csv" "$CORES" <<'PY'
import csv, datetime, glob, json, os, socket, sys
work, path, cores = sys.argv[1], sys.argv[2], int(sys.argv[3])
one = json.load(open(f"{work}/r1/summary.json"))
base = one["benchmark"]["particle_steps_per_s"]
print(f"heap: {one['particles']} grains at the end; one rank {base:.4e} particle-steps/s (timed segment)")
print(f"{'P':>3} {'balance':>8} {'psps':>12} {'efficiency':>10} {'imbalance':>9} {'halo':>6} {'rebalances':>10}")
new = not os.path.exists(path)
with open(path, "a", newline="") as f:
    w = csv.writer(f)
    if new:
        w.writerow(["date", "host", "ranks", "load_balance", "psps", "psps_one_rank", "efficiency",
                    "mean_imbalance", "halo_share", "rebalances", "oversubscribed"])
    for d in sorted(glob.glob(f"{work}/r*_*"), key=lambda p: (int(p.rsplit("/r", 1)[1].split("_")[0]), p)):
        s = json.load(open(f"{d}/summary.json"))
        p = s["ranks"]
        dom = s["domains"]
        rate = s["benchmark"]["particle_steps_per_s"]
        eff = rate / (p * base)
        over = p > cores
        note = " (oversubscribed: timing not meaningful)" if over else ""
        print(f"{p:>3} {str(dom['load_balance']):>8} {rate:12.4e} {eff:10.2f} {dom['mean_imbalance']:9.3f} "
              f"{dom['halo_share']:6.3f} {dom['rebalances']:>10}{note}")
        w.writerow([datetime.datetime.now().isoformat(timespec="seconds"), socket.gethostname(), p,
                    int(dom["load_balance"]), f"{rate:.6g}", f"{base:.6g}", f"{eff:.4f}",
                    f"{dom['mean_imbalance']:.4f}", f"{dom['halo_share']:.4f}", dom["rebalances"], int(over)])
print(f"appended to {path}")
PY
