#!/usr/bin/env bash
# Scaling table of the parallel event-driven engine (issue 15; edmd spec 3, AT-4/AT-5): for each
# rank count P of the list, with build/bench/granulab_bench_edmd_parallel (elastic hard disks or
# spheres, periodic box, lattice start):
#   strong  N particles on P ranks against the serial engine on the same N (the serial run is
#           repeated right before each parallel run, so drifting machine speed cancels);
#   weak    W particles per rank (N = P W) against the serial engine on W;
#   cluster a cooling gas (restitution EPS, TC model) of N particles on P >= 3 ranks with and
#           without load balancing, against the elastic gas on the same ranks (the issue's
#           "keeps 70 % of the homogeneous rate").
# Each line: ranks, collisions/s, speed-up (or efficiency), rollbacks per section, communication
# share of a rank's loop, event imbalance (busiest rank over the mean) and bytes per particle per
# rank. Written to RESULTS_DIR/edmd_parallel_scaling.csv. Meant for a machine with at least
# max(P) cores; with fewer, the ranks share cores (--oversubscribe) and the timings mean nothing.
# A cooling gas clusters only after tens of collisions per particle: run the cluster kind with a
# larger -c (e.g. -k cluster -c 40).
#
# Usage: bench/edmd_parallel_scaling.sh [-P "2 4 8 16"] [-d 2] [-N 1e6] [-W 1e5] [-n 0.3] [-c 4]
#            [-e 0.5] [-r 1] [-k strong,weak,cluster]
# Env: BENCH (default <repo>/build/bench/granulab_bench_edmd_parallel), MPIRUN (default mpirun),
#      MPIRUN_FLAGS (default "--bind-to core --mca btl_vader_single_copy_mechanism none"; add
#      --oversubscribe where there are fewer cores than ranks, --allow-run-as-root as root),
#      RESULTS_DIR (default <repo>/bench/results/<hostname>).
# On a machine without packages, carry Open MPI with ../shared/offline-mpi/bundle.sh and set
# PATH, OPAL_PREFIX and LD_LIBRARY_PATH as that script says.
set -euo pipefail

RANKS="2 4 8 16" DIM=2 N=1e6 W=1e5 NU=0.3 COLL=4 EPS=0.5 REPEAT=1 KINDS=strong,weak,cluster
while getopts "P:d:N:W:n:c:e:r:k:h" opt; do
    case $opt in
        P) RANKS=$OPTARG ;;
        d) DIM=$OPTARG ;;
        N) N=$OPTARG ;;
        W) W=$OPTARG ;;
        n) NU=$OPTARG ;;
        c) COLL=$OPTARG ;;
        e) EPS=$OPTARG ;;
        r) REPEAT=$OPTARG ;;
        k) KINDS=$OPTARG ;;
        h) sed -n '2,25p' "$0"; exit 0 ;;
        *) sed -n '2,25p' "$0" >&2; exit 2 ;;
    esac
done
ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel 2>/dev/null || (cd "$(dirname "$0")/.." && pwd))
BENCH=${BENCH:-"$ROOT/build/bench/granulab_bench_edmd_parallel"}
MPIRUN=${MPIRUN:-mpirun}
MPIRUN_FLAGS=${MPIRUN_FLAGS:-"--bind-to core --mca btl_vader_single_copy_mechanism none"}
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$(hostname)"}
[[ -x $BENCH ]] || { echo "error: $BENCH not built (cmake --build build --target granulab_bench_edmd_parallel)" >&2; exit 2; }
mkdir -p "$RESULTS_DIR"
OUT="$RESULTS_DIR/edmd_parallel_scaling.csv"
[[ -f $OUT ]] || echo "kind,dim,ranks,particles,collisions_per_s,reference_collisions_per_s,ratio,rollbacks,sections,communication_share,imbalance,bytes_per_particle_per_rank,balancing" > "$OUT"

# field LINE KEY: the value of key=value in the benchmark's output line.
field() { tr ' ' '\n' <<< "$1" | awk -F= -v k="$2" '$1 == k { print $2 }'; }
serial() { "$BENCH" --serial --dim "$DIM" --fraction "$NU" --collisions "$COLL" "$@" | tail -1; }
parallel() {
    local p=$1
    shift
    # shellcheck disable=SC2086
    $MPIRUN -np "$p" $MPIRUN_FLAGS "$BENCH" --dim "$DIM" --fraction "$NU" --collisions "$COLL" "$@" | tail -1
}
# report KIND P LINE REFERENCE_RATE BALANCING: one table line and one CSV row.
report() {
    local kind=$1 p=$2 line=$3 ref=$4 balancing=$5
    local rate sections rollbacks compute comm
    rate=$(field "$line" collisions_per_s)
    sections=$(field "$line" sections)
    rollbacks=$(field "$line" rollbacks)
    compute=$(field "$line" compute_s)
    comm=$(field "$line" communication_s)
    python3 - "$kind" "$DIM" "$p" "$(field "$line" particles)" "$rate" "$ref" "$rollbacks" "$sections" \
        "$compute" "$comm" "$(field "$line" imbalance)" "$(field "$line" bytes_per_particle_per_rank)" \
        "$balancing" "$OUT" <<'PY'
import sys
kind, dim, p, n, rate, ref, rollbacks, sections, compute, comm, imbalance, bpp, balancing, out = sys.argv[1:]
rate, ref = float(rate), float(ref)
ratio = rate / ref / (int(p) if kind == "weak" else 1)
share = float(comm) / (float(compute) + float(comm)) if float(compute) + float(comm) > 0 else 0
print(f"{kind:8s} P={p:>3s} N={int(float(n)):>9d}  {rate:10.4g} coll/s  ref {ref:10.4g}  "
      f"{'efficiency' if kind == 'weak' else 'ratio'} {ratio:6.3f}  rollbacks {rollbacks}/{sections} sections  "
      f"comm {share:5.1%}  imbalance {imbalance}  {bpp} B/particle/rank  balancing {balancing}")
with open(out, "a") as f:
    f.write(f"{kind},{dim},{p},{n},{rate},{ref},{ratio:.4f},{rollbacks},{sections},{share:.4f},{imbalance},{bpp},{balancing}\n")
PY
}

for ((rep = 1; rep <= REPEAT; rep++)); do
    for P in $RANKS; do
        if [[ ,$KINDS, == *,strong,* ]]; then
            ref=$(field "$(serial --particles "$N")" collisions_per_s)
            report strong "$P" "$(parallel "$P" --particles "$N")" "$ref" yes
        fi
        if [[ ,$KINDS, == *,weak,* ]]; then
            ref=$(field "$(serial --particles "$W")" collisions_per_s)
            total=$(python3 -c "print($P * $W)")
            report weak "$P" "$(parallel "$P" --particles "$total")" "$ref" yes
        fi
        if [[ ,$KINDS, == *,cluster,* && $P -ge 3 ]]; then
            ref=$(field "$(parallel "$P" --particles "$N")" collisions_per_s)
            report cluster "$P" "$(parallel "$P" --particles "$N" --restitution "$EPS")" "$ref" yes
            report cluster "$P" "$(parallel "$P" --particles "$N" --restitution "$EPS" --no-balance)" "$ref" no
        fi
    done
done
echo "wrote $OUT"
