#!/usr/bin/env bash
# Settled-bed throughput benchmark: granulab (examples/bench/disk_bed.toml) against LAMMPS
# (../shared/peers/in.disk2d_bed.lmp, run unedited through bench/lammps/disk_bed_wrap.lmp),
# one after the other, on the same N = NX*NX disks: serially, or (-p P) LAMMPS on P MPI ranks
# (mpirun -np P --bind-to core) against granulab on P threads, or (-m) granulab on P MPI ranks
# too (domain decomposition, docs/physics/dem-mpi.md). Prints throughput of the timed
# segment, whole-job wall times, final kinetic energies and bed heights of both, and a verdict.
# See bench/README.md.
#
# Usage: bench/disk_bed_vs_lammps.sh [-n NX] [-r REPEATS] [-s SETTLE] [-t TSTEPS] [-p P] [-m] [-k]
#   -n NX       disks per row and number of rows (default 100 -> N = 10,000)
#   -r REPEATS  run each code REPEATS times, report the median timings (default 1)
#   -s SETTLE   damped settling steps (default 60000, as the peer file)
#   -t TSTEPS   timed steps (default 10000, as the peer file)
#   -p P        LAMMPS on P MPI ranks, granulab on P threads (default 1: both serial)
#   -m          granulab on P MPI ranks of one thread each, as LAMMPS (with -p)
#   -k          keep the work directory (printed at the end)
# Env: PEER_DIR (folder of in.disk2d_bed.lmp; default <repo>/../shared/peers),
#      GRANULAB (binary; default <repo>/build/granulab, built by scripts/setup.sh), LMP (default lmp),
#      RESULTS_DIR (default <repo>/bench/results/<hostname>).
set -euo pipefail

NX=100 REPEATS=1 SETTLE=60000 TSTEPS=10000 KEEP=0 PROCS=1 MPI=0
while getopts "n:r:s:t:p:mkh" opt; do
    case $opt in
        n) NX=$OPTARG ;;
        r) REPEATS=$OPTARG ;;
        s) SETTLE=$OPTARG ;;
        t) TSTEPS=$OPTARG ;;
        p) PROCS=$OPTARG ;;
        m) MPI=1 ;;
        k) KEEP=1 ;;
        h) sed -n '2,18p' "$0"; exit 0 ;;
        *) sed -n '2,18p' "$0" >&2; exit 2 ;;
    esac
done
for v in "$NX" "$REPEATS" "$SETTLE" "$TSTEPS" "$PROCS"; do
    [[ $v =~ ^[1-9][0-9]*$ ]] || { echo "error: options need positive integers (got '$v')" >&2; exit 2; }
done

ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
PEER_DIR=${PEER_DIR:-"$ROOT/../shared/peers"}
PEER="$PEER_DIR/in.disk2d_bed.lmp"
WRAP="$ROOT/bench/lammps/disk_bed_wrap.lmp"
SCENE="$ROOT/examples/bench/disk_bed.toml"
GRANULAB=${GRANULAB:-"$ROOT/build/granulab"}
LMP=${LMP:-lmp}
HOST=$(hostname)
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$HOST"}

[[ -f $PEER ]] || { echo "error: peer input not found: $PEER (set PEER_DIR)" >&2; exit 1; }
[[ -x $GRANULAB ]] || { echo "error: granulab binary not found: $GRANULAB (build it with scripts/setup.sh, or set GRANULAB)" >&2; exit 1; }
command -v "$LMP" >/dev/null || { echo "error: LAMMPS executable '$LMP' not found (set LMP)" >&2; exit 1; }
LAUNCH=()  # LAMMPS on PROCS ranks; Open MPI refuses root unless told
if ((PROCS > 1)); then
    command -v mpirun >/dev/null || { echo "error: -p needs mpirun (apt-get install openmpi-bin)" >&2; exit 1; }
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    LAUNCH=(mpirun -np "$PROCS" --bind-to core)
fi
GLAUNCH=()  # granulab: P threads, or (-m) P ranks of one thread
if ((MPI == 1 && PROCS > 1)); then GLAUNCH=("${LAUNCH[@]}"); fi
if busy=$(pgrep -af 'granulab_tests|granulab_bench|granulab run|lmp -in' 2>/dev/null) && [[ -n $busy ]]; then
    echo "warning: other jobs are running; timings may be disturbed:" >&2
    echo "$busy" | cut -c1-120 >&2
fi

WORK=$(mktemp -d "${TMPDIR:-/tmp}/disk_bed_vs_lammps.XXXXXX")
[[ $KEEP == 1 ]] || trap 'rm -rf "$WORK"' EXIT

# Geometry of the peer's lattice, replicated for granulab. LAMMPS `lattice hex` with spacing
# a = 1.12, origin (0.5, 0.3) cell units, fills [0.1, W] x [0, HF] with W = NX a + 0.56 and
# HF = NY a sqrt(3)/2: sites at x = 0.56 + i a (even rows) and 1.12 + i a (odd rows), i < NX,
# i.e. up to NX a; xmax = NX a + 0.3 keeps those and drops 0.56 + NX a. Walls: x = 0, x = W,
# y = 0; the granulab side walls reach far above the bed.
NY=$NX
read -r XMAX YMAX W WTOP T_BENCH T_END T_DAMP < <(python3 -c "
import math
nx, ny, s, t = $NX, $NY, $SETTLE, $TSTEPS
a = 1.12
hf = ny * a * math.sqrt(3) / 2
print(f'{nx*a+0.3:.10g} {hf:.10g} {nx*a+0.56:.10g} {max(400.0, 4*hf):.10g} '
      f'{(s+2000)*1e-4:.10g} {(s+2000+t)*1e-4:.10g} {s*1e-4:.10g}')")

GTHREADS=$PROCS
((MPI == 0)) || GTHREADS=1
gset=(--threads "$GTHREADS"
      --set "block[0].region=[0.1,0.0,$XMAX,$YMAX]"
      --set "wall[0].points=[[0.0,$WTOP],[0.0,0.0],[$W,0.0],[$W,$WTOP]]"
      --set "dem.damping[0].to=$T_DAMP"
      --set "run.benchmark_from=$T_BENCH"
      --set "run.end_time=$T_END")
# On several ranks a series row gathers every particle to the root (docs/physics/dem-mpi.md):
# one row per 10,000 steps, as the peer's thermo output is cheap and granulab's is not.
((MPI == 0)) || gset+=(--set "output.series_interval=1.0")

now() { date +%s.%N; }

echo "disk bed: N = $NX x $NY = $((NX * NY)) disks, settle $SETTLE + 2000 steps, timed $TSTEPS steps, $REPEATS repeat(s), LAMMPS on $PROCS rank(s), granulab on $PROCS $( ((MPI == 1)) && echo "rank(s)" || echo "thread(s)")"
for ((k = 1; k <= REPEATS; ++k)); do
    d="$WORK/rep$k"
    mkdir -p "$d/lammps"
    run_lammps() {
        echo "[$k/$REPEATS] LAMMPS ..." >&2
        local t0 t1
        t0=$(now)
        (cd "$d/lammps" && "${LAUNCH[@]}" "$LMP" -in "$WRAP" -var peer "$PEER" -var dumpfile "$d/lammps/final.dump" \
            -var nx "$NX" -var ny "$NY" -var settle "$SETTLE" -var tsteps "$TSTEPS" \
            -log "$d/lammps/log.lammps" -screen none) ||
            { echo "error: LAMMPS failed, see $d/lammps/log.lammps" >&2; KEEP=1; trap - EXIT; exit 1; }
        t1=$(now)
        wl=$(python3 -c "print($t1 - $t0)")
    }
    run_granulab() {
        echo "[$k/$REPEATS] granulab ..." >&2
        local t0 t1
        t0=$(now)
        "${GLAUNCH[@]}" "$GRANULAB" run "$SCENE" --out "$d/granulab" --quiet "${gset[@]}" ||
            { echo "error: granulab failed (output in $d/granulab)" >&2; KEEP=1; trap - EXIT; exit 1; }
        t1=$(now)
        wg=$(python3 -c "print($t1 - $t0)")
    }
    # Alternate the order: a code that runs right after a long run on every core can find the
    # machine slower (measured on the shared 2-core VM: granulab at half speed after LAMMPS).
    if ((k % 2 == 1)); then run_lammps; run_granulab; else run_granulab; run_lammps; fi
    echo "0 $wl $wg" > "$d/walls.txt"
done

mkdir -p "$RESULTS_DIR"
rc=0
CSV="$RESULTS_DIR/disk_bed.csv"
((PROCS == 1)) || CSV="$RESULTS_DIR/disk_bed_p$PROCS.csv"  # P ranks / threads: a table of its own
((PROCS == 1 || MPI == 0)) || CSV="$RESULTS_DIR/disk_bed_p${PROCS}_mpi.csv"
python3 - "$WORK" "$REPEATS" "$NX" "$NY" "$CSV" "$HOST" "$TSTEPS" <<'EOF' || rc=$?
import csv, datetime, json, math, os, re, statistics, sys

work, reps, nx, ny, csv_path, host, tsteps = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5], sys.argv[6], int(sys.argv[7])
N = nx * ny

def lammps_log(path):
    text = open(path).read().splitlines()
    loops = [l for l in text if l.startswith("Loop time of")]
    m = re.match(r"Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms", loops[-1])
    loop, steps, atoms = float(m.group(1)), int(m.group(3)), int(m.group(4))
    # last thermo line of the last run: the numeric line just before the last "Loop time"
    last = max(i for i, l in enumerate(text) if l.startswith("Loop time of"))
    head = max(i for i in range(last) if text[i].split()[:1] == ["Step"])
    cols = text[head].split()
    vals = None
    for l in text[head + 1:last]:
        f = l.split()
        if len(f) == len(cols):
            try: vals = [float(x) for x in f]
            except ValueError: pass
    th = dict(zip(cols, vals))
    ver = next((l for l in text if l.startswith("LAMMPS (")), "LAMMPS (?)")
    return dict(loop=loop, steps=steps, atoms=atoms, ke=th["KinEng"], rke=th["c_rke"], version=ver)

def lammps_dump(path):
    lines = open(path).read().splitlines()
    i = lines.index(next(l for l in lines if l.startswith("ITEM: ATOMS")))
    cols = lines[i].split()[2:]
    rows = [dict(zip(cols, map(float, l.split()))) for l in lines[i + 1:] if l.strip()]
    return rows

def granulab_final(path):
    with open(path) as f:
        return [{k: (float(v) if k not in ("shape", "material") else v) for k, v in r.items()} for r in csv.DictReader(f)]

def med(xs): return statistics.median(xs)

L, G, wl, wg = [], [], [], []
for k in range(1, reps + 1):
    d = os.path.join(work, f"rep{k}")
    L.append(lammps_log(os.path.join(d, "lammps", "log.lammps")))
    G.append(json.load(open(os.path.join(d, "granulab", "summary.json"))))
    _, t_l, t_g = map(float, open(os.path.join(d, "walls.txt")).read().split())
    wl.append(t_l); wg.append(t_g)

d = os.path.join(work, f"rep{reps}")
ld = lammps_dump(os.path.join(d, "lammps", "final.dump"))
gd = granulab_final(os.path.join(d, "granulab", "final.csv"))
lg, gs = L[-1], G[-1]
problems = []
if lg["atoms"] != N or gs["particles"] != N or len(ld) != N or len(gd) != N:
    problems.append(f"particle counts differ: expected {N}, LAMMPS {lg['atoms']} (dump {len(ld)}), granulab {gs['particles']}")
if lg["steps"] != tsteps or gs["benchmark"]["steps"] != tsteps:
    problems.append(f"timed steps differ: LAMMPS {lg['steps']}, granulab {gs['benchmark']['steps']}")

tl = med([N * x["steps"] / x["loop"] for x in L])
tg = med([x["benchmark"]["particle_steps_per_s"] for x in G])
WL, WG = med(wl), med(wg)

# energies: LAMMPS thermo (norm no -> totals); c_rke is compute erotate/sphere, which uses the
# SPHERE inertia 0.4 m r^2 although nve/sphere disc integrates with 0.5 m r^2, so the disc
# rotational energy is recomputed from the dump (= 1.25 c_rke).
ke_l, rke_l_raw = lg["ke"], lg["rke"]
ke_l_dump = sum(0.5 * r["mass"] * (r["vx"] ** 2 + r["vy"] ** 2) for r in ld)
rke_l = sum(0.25 * r["mass"] * r["radius"] ** 2 * r["omegaz"] ** 2 for r in ld)
ke_g, rke_g = gs["energy"]["kinetic"], gs["energy"]["rotational"]
# initial potential-energy scale: granulab's t = 0 row (same lattice as LAMMPS, y measured from the floor)
with open(os.path.join(d, "granulab", "series.csv")) as f:
    pe0 = float(next(csv.DictReader(f))["potential_energy"])
# heights
hmax_l = max(r["y"] + r["radius"] for r in ld); hmax_g = max(r["y"] + r["radius"] for r in gd)
ymean_l = sum(r["y"] for r in ld) / len(ld); ymean_g = sum(r["y"] for r in gd) / len(gd)
if abs(hmax_g - gs["max_height"]) > 1e-9 * hmax_g:
    problems.append(f"granulab max_height {gs['max_height']} != max(y+r) of final.csv {hmax_g}")

rel = lambda a, b: (a - b) / b
thr = 1e-5 * pe0
h_ok = abs(rel(hmax_g, hmax_l)) < 0.01 and abs(rel(ymean_g, ymean_l)) < 0.01
ke_ok = (ke_l + rke_l) < thr and (ke_g + rke_g) < thr

w = 34
def row(name, a, b, r=None, fmt="{:.4g}"):
    ra = "" if r is None else f"{r:9.3f}"
    print(f"  {name:<{w}} {fmt.format(a):>13} {fmt.format(b):>13} {ra:>9}")

procs = re.match(r"Loop time of \S+ on (\d+) procs", [l for l in open(os.path.join(d, "lammps", "log.lammps")) if l.startswith("Loop time of")][-1]).group(1)
print(f"LAMMPS: {lg['version']} ({procs} MPI rank(s), {lg['atoms']} atoms); granulab: {gs['version']} ({gs['integrator']}, {gs['broad_phase']}, {gs.get('ranks', 1)} MPI rank(s) x {gs.get('threads', 1)} thread(s))")
med_note = f" (median of {reps})" if reps > 1 else ""
print(f"  {'quantity':<{w}} {'granulab':>13} {'LAMMPS':>13} {'g/L':>9}")
row(f"timed particle-steps/s{med_note}", tg, tl, tg / tl, "{:.4e}")
row(f"timed segment wall [s]", N * tsteps / tg, N * tsteps / tl, tl / tg, "{:.3f}")
row(f"whole job wall [s]{med_note}", WG, WL, WG / WL, "{:.2f}")
row("final KE translational", ke_g, ke_l, ke_g / ke_l if ke_l else float("nan"), "{:.4g}")
row("final KE rotational (disc I)", rke_g, rke_l, rke_g / rke_l if rke_l else float("nan"), "{:.4g}")
print(f"  {'  (LAMMPS c_rke, sphere I = 0.4mr^2)':<{w}} {'':>13} {rke_l_raw:>13.4g}")
row("bed height max(y+r)", hmax_g, hmax_l, hmax_g / hmax_l, "{:.4f}")
row("mean y", ymean_g, ymean_l, ymean_g / ymean_l, "{:.4f}")
print(f"  initial potential energy {pe0:.5g} -> static threshold 1e-5 * PE0 = {thr:.4g}")
print(f"verdict: heights {'AGREE' if h_ok else 'DISAGREE'} within 1 % "
      f"(max {100*rel(hmax_g, hmax_l):+.3f} %, mean y {100*rel(ymean_g, ymean_l):+.3f} %); "
      f"beds {'both STATIC' if ke_ok else 'NOT both static'} "
      f"(KE+rot: granulab {ke_g + rke_g:.3g}, LAMMPS {ke_l + rke_l:.3g}, limit {thr:.3g})")
if abs(ke_l_dump - ke_l) > 1e-6 * max(1.0, ke_l):
    problems.append(f"LAMMPS thermo KE {ke_l} != dump KE {ke_l_dump}")
for p in problems: print("problem:", p)

new = not os.path.exists(csv_path)
with open(csv_path, "a", newline="") as f:
    wr = csv.writer(f)
    if new:
        wr.writerow(["date", "host", "N", "repeats", "tsteps", "granulab_psps", "lammps_psps", "ratio_g_over_l",
                     "granulab_job_s", "lammps_job_s", "ke_granulab", "ke_lammps", "rke_granulab", "rke_lammps_disc",
                     "hmax_granulab", "hmax_lammps", "ymean_granulab", "ymean_lammps", "heights_agree", "static"])
    wr.writerow([datetime.datetime.now().isoformat(timespec="seconds"), host, N, reps, tsteps,
                 f"{tg:.6g}", f"{tl:.6g}", f"{tg/tl:.4f}", f"{WG:.3f}", f"{WL:.3f}",
                 f"{ke_g:.6g}", f"{ke_l:.6g}", f"{rke_g:.6g}", f"{rke_l:.6g}",
                 f"{hmax_g:.6f}", f"{hmax_l:.6f}", f"{ymean_g:.6f}", f"{ymean_l:.6f}", int(h_ok), int(ke_ok)])
print(f"appended to {csv_path}")
sys.exit(0 if not problems else 1)
EOF
[[ $KEEP == 1 ]] && echo "work directory kept: $WORK"
exit $rc
