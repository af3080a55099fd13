#!/usr/bin/env bash
# Scaling table of the DEM domain decomposition (issue 16; docs/physics/dem-mpi.md): the settled
# disk bed of bench/disk_bed_vs_lammps.sh on P = 1, 2, 4, ... MPI ranks of one thread each,
# granulab against LAMMPS on the same rank count, one after the other. Prints, per P: both codes'
# particle-steps/s of the timed segment, granulab's speed-up and parallel efficiency against its
# own one-rank run, the ratio to LAMMPS, and the decomposition's imbalance and halo share
# (summary.json "domains"). Appends the rows to $RESULTS_DIR/dem_mpi_scaling.csv.
#
# Usage: bench/dem_mpi_scaling.sh [-n NX] [-s SETTLE] [-t TSTEPS] [-P "1 2 4 8 16"]
#   -n NX       disks per row and rows (default 100: N = 10,000; 1000: the issue's 1e6)
#   -s SETTLE   damped settling steps (default 60000; fewer for 1e6 disks: the timing does not
#               need a settled bed, only the same workload for both codes)
#   -t TSTEPS   timed steps (default 10000)
#   -P LIST     rank counts (default "1 2 4 8 16", those above the cores are skipped)
# Env: as bench/disk_bed_vs_lammps.sh (GRANULAB, LMP, PEER_DIR, RESULTS_DIR).
# On a machine without packages, OpenMPI and LAMMPS come from ../shared/offline-mpi/bundle.sh.
set -euo pipefail
NX=100 SETTLE=60000 TSTEPS=10000 LIST="1 2 4 8 16"
while getopts "n:s:t:P:h" opt; do
    case $opt in
        n) NX=$OPTARG ;;
        s) SETTLE=$OPTARG ;;
        t) TSTEPS=$OPTARG ;;
        P) LIST=$OPTARG ;;
        h) sed -n '2,17p' "$0"; exit 0 ;;
        *) sed -n '2,17p' "$0" >&2; exit 2 ;;
    esac
done
ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
HOST=$(hostname)
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$HOST"}
CORES=$(nproc)
mkdir -p "$RESULTS_DIR"
ROWS=$(mktemp)
trap 'rm -f "$ROWS"' EXIT
for P in $LIST; do
    if ((P > CORES)); then echo "skipping P = $P: $CORES cores" >&2; continue; fi
    flags=(-n "$NX" -s "$SETTLE" -t "$TSTEPS" -p "$P" -k)
    ((P == 1)) || flags+=(-m)
    out=$("$ROOT/bench/disk_bed_vs_lammps.sh" "${flags[@]}" | tee /dev/stderr)
    work=$(echo "$out" | sed -n 's/^work directory kept: //p')
    echo "$P $work" >>"$ROWS"
done
python3 - "$ROWS" "$NX" "$RESULTS_DIR/dem_mpi_scaling.csv" "$HOST" <<'PY'
import csv, datetime, json, os, re, sys
rows, nx, path, host = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
N = nx * nx
table = []
for line in open(rows):
    p, work = line.split(maxsplit=1)
    d = os.path.join(work.strip(), "rep1")
    g = json.load(open(os.path.join(d, "granulab", "summary.json")))
    log = open(os.path.join(d, "lammps", "log.lammps")).read().splitlines()
    m = re.match(r"Loop time of (\S+) on \d+ procs for (\d+) steps", [l for l in log if l.startswith("Loop time of")][-1])
    lammps = N * int(m.group(2)) / float(m.group(1))
    dom = g.get("domains", {})
    table.append((int(p), g["benchmark"]["particle_steps_per_s"], lammps, dom.get("mean_imbalance", 1.0),
                  dom.get("halo_share", 0.0)))
base = next((t[1] for t in table if t[0] == 1), None)
print(f"N = {N} disks; particle-steps/s of the timed segment")
print(f"{'P':>3} {'granulab':>12} {'LAMMPS':>12} {'g/L':>6} {'speed-up':>9} {'efficiency':>10} {'imbalance':>9} {'halo':>6}")
new = not os.path.exists(path)
with open(path, "a", newline="") as f:
    w = csv.writer(f)
    if new:
        w.writerow(["date", "host", "N", "ranks", "granulab_psps", "lammps_psps", "ratio_g_over_l", "speedup",
                    "efficiency", "mean_imbalance", "halo_share"])
    for p, gr, lr, imb, halo in table:
        s = gr / base if base else float("nan")
        print(f"{p:>3} {gr:12.4e} {lr:12.4e} {gr/lr:6.2f} {s:9.2f} {s/p:10.2f} {imb:9.3f} {halo:6.3f}")
        w.writerow([datetime.datetime.now().isoformat(timespec="seconds"), host, N, p, f"{gr:.6g}", f"{lr:.6g}",
                    f"{gr/lr:.4f}", f"{s:.4f}", f"{s/p:.4f}", f"{imb:.4f}", f"{halo:.4f}"])
print(f"appended to {path}")
PY
