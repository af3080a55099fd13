#!/usr/bin/env bash
# Size scaling of granulab on a dense static bed (the laws, walls, gravity and time step of
# examples/bench/disk_bed.toml): cost per particle-step, engine bytes per particle and peak RSS
# per disk for N = 1e4, 1e5, 1e6. Every size is a bed of the same height, NY = 100 rows of a
# touching hexagonal packing (r = 0.5, spacing 1.0, so every disk starts in contact like a
# settled bed), and NX = N / 100 columns: each disk sees the same pressure and contacts at every
# N, so only the size changes. (A bed falling from the loose lattice has almost no contacts and a
# square NX x NX bed is ten times taller at 1e6; neither measures what the settled bed costs.)
# The run is WARMUP steps of damped settling, then a timed segment of STEPS steps (summary.json
# "benchmark"). VTK snapshots are switched off (output.vtk=false). See bench/README.md.
#
# Usage: bench/scaling.sh [-N "10000 100000 1000000"] [-w WARMUP] [-s STEPS] [-k]
#   -N SIZES   particle counts (default "10000 100000 1000000")
#   -w WARMUP  untimed steps before the timed segment (default 500)
#   -s STEPS   timed steps (default 2000)
#   -k         keep the work directory
# Env: THREADS (granulab threads, default 1), GRANULAB (binary; default <repo>/build/granulab, built by scripts/setup.sh), RESULTS_DIR
#      (default <repo>/bench/results/<hostname>).
set -euo pipefail
THREADS=${THREADS:-1}  # granulab threads (run.threads); 1: the serial kernel

SIZES="10000 100000 1000000" WARMUP=500 STEPS=2000 KEEP=0
while getopts "N:w:s:kh" opt; do
    case $opt in
        N) SIZES=$OPTARG ;;
        w) WARMUP=$OPTARG ;;
        s) STEPS=$OPTARG ;;
        k) KEEP=1 ;;
        h) sed -n '2,16p' "$0"; exit 0 ;;
        *) sed -n '2,16p' "$0" >&2; exit 2 ;;
    esac
done
for v in $SIZES "$WARMUP" "$STEPS"; do
    [[ $v =~ ^[1-9][0-9]*$ ]] || { echo "error: options need positive integers (got '$v')" >&2; exit 2; }
done

ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
SCENE="$ROOT/examples/bench/disk_bed.toml"
GRANULAB=${GRANULAB:-"$ROOT/build/granulab"}
HOST=$(hostname)
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$HOST"}
[[ -x $GRANULAB ]] || { echo "error: granulab binary not found: $GRANULAB (build it with scripts/setup.sh, or set GRANULAB)" >&2; exit 1; }
if busy=$(pgrep -af 'granulab_tests|granulab_bench|granulab run|lmp -in' 2>/dev/null) && [[ -n $busy ]]; then
    echo "warning: other jobs are running; timings may be disturbed:" >&2
    echo "$busy" | cut -c1-120 >&2
fi

WORK=$(mktemp -d "${TMPDIR:-/tmp}/granulab_scaling.XXXXXX")
[[ $KEEP == 1 ]] || trap 'rm -rf "$WORK"' EXIT

echo "granulab scaling, dense static bed of 100 rows: $WARMUP untimed + $STEPS timed steps per size ($GRANULAB)"
for n in $SIZES; do
    # geometry as in bench/disk_bed_vs_lammps.sh: lattice spacing 1.12, xmax = NX a + 0.3,
    # ymax = NY a sqrt(3)/2, side walls at x = 0 and W = NX a + 0.56 reaching 4 ymax (>= 400)
    read -r NX NY XMAX YMAX W WTOP T_BENCH T_END < <(python3 -c "
import math
n, w, s = $n, $WARMUP, $STEPS
ny = 100; nx = max(1, round(n / ny)); a = 1.0
hf = 0.5 + (ny - 0.5) * a * math.sqrt(3) / 2
print(nx, ny, f'{0.5+(nx-0.25)*a:.10g} {hf:.10g} {0.5+nx*a:.10g} {max(400.0, 4*hf):.10g} {w*1e-4:.10g} {(w+s)*1e-4:.10g}')")
    d="$WORK/n$n"
    echo "  N = $n ($NX x $NY) ..." >&2
    t0=$(date +%s.%N)
    "$GRANULAB" run --threads "$THREADS" "$SCENE" --out "$d" --quiet \
        --set block[0].spacing=1.0 --set block[0].radius=0.5 --set "block[0].origin=[0.5,0.5]" \
        --set "block[0].region=[0.4,0.0,$XMAX,$YMAX]" --set block[0].temperature=0.0 \
        --set "dem.damping[0].to=$T_BENCH" \
        --set "wall[0].points=[[0.0,$WTOP],[0.0,0.0],[$W,0.0],[$W,$WTOP]]" \
        --set "run.benchmark_from=$T_BENCH" --set "run.end_time=$T_END" \
        --set output.vtk=false --set output.checkpoint_interval=$T_END ||
        { echo "error: granulab failed for N = $n (output in $d)" >&2; KEEP=1; trap - EXIT; exit 1; }
    t1=$(date +%s.%N)
    echo "$n $NX $NY $t0 $t1" >> "$WORK/runs.txt"
done

mkdir -p "$RESULTS_DIR"
rc=0
python3 - "$WORK" "$RESULTS_DIR/scaling.csv" "$HOST" "$WARMUP" "$STEPS" <<'EOF' || rc=$?
import csv, datetime, json, os, sys
work, csv_path, host, warmup, steps = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
rows = []
for line in open(os.path.join(work, "runs.txt")):
    n, nx, ny, t0, t1 = line.split()
    s = json.load(open(os.path.join(work, f"n{n}", "summary.json")))
    N = s["particles"]
    b = s["benchmark"]
    ns = 1e9 * b["wall_s"] / (N * b["steps"])
    engine = sum(v for k, v in s["timers_s"].items() if k != "output")
    ns_engine = 1e9 * engine / (N * s["steps"])
    rows.append(dict(n=int(n), N=N, nx=int(nx), ny=int(ny), ns=ns, ns_engine=ns_engine, psps=b["particle_steps_per_s"],
                     bpp=s["bytes_per_particle"], rss=s["peak_rss_bytes"] / N, rss_mb=s["peak_rss_bytes"] / 2**20,
                     job=float(t1) - float(t0), out=s["timers_s"]["output"], pairs=s["candidate_pairs"] / N,
                     builds=s["neighbor_builds"], status=s["status"]))
print(f"  {'N':>9} {'NX x NY':>11} {'ns/p-step':>10} {'engine ns':>10} {'p-steps/s':>11} {'B/particle':>11} "
      f"{'RSS B/disk':>11} {'RSS MiB':>8} {'pairs/p':>8} {'job s':>7}")
for r in rows:
    print(f"  {r['N']:>9} {str(r['nx'])+' x '+str(r['ny']):>11} {r['ns']:>10.2f} {r['ns_engine']:>10.2f} {r['psps']:>11.4g} "
          f"{r['bpp']:>11.1f} {r['rss']:>11.1f} {r['rss_mb']:>8.1f} {r['pairs']:>8.3f} {r['job']:>7.1f}")
cost = [r["ns"] for r in rows]
ratio = max(cost) / min(cost)
print(f"  max/min cost per particle-step across sizes: {ratio:.3f} "
      f"(timed segment; 'engine ns' = stage timers over all {warmup + steps} steps, without output)")
bad = [r for r in rows if r["status"] != "completed"]
for r in bad: print(f"problem: N = {r['N']} ended with status {r['status']}")
new = not os.path.exists(csv_path)
with open(csv_path, "a", newline="") as f:
    w = csv.writer(f)
    if new:
        w.writerow(["date", "host", "N", "nx", "ny", "warmup_steps", "timed_steps", "ns_per_particle_step",
                    "engine_ns_per_particle_step", "particle_steps_per_s", "bytes_per_particle",
                    "peak_rss_bytes_per_particle", "candidate_pairs_per_particle", "job_wall_s", "max_min_cost_ratio"])
    now = datetime.datetime.now().isoformat(timespec="seconds")
    for r in rows:
        w.writerow([now, host, r["N"], r["nx"], r["ny"], warmup, steps, f"{r['ns']:.4f}", f"{r['ns_engine']:.4f}",
                    f"{r['psps']:.6g}", f"{r['bpp']:.2f}", f"{r['rss']:.2f}", f"{r['pairs']:.4f}", f"{r['job']:.2f}",
                    f"{ratio:.4f}"])
print(f"appended to {csv_path}")
sys.exit(1 if bad else 0)
EOF
[[ $KEEP == 1 ]] && echo "work directory kept: $WORK"
exit $rc
