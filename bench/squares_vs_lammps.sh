#!/usr/bin/env bash
# Polygon throughput benchmark: granulab (examples/bench/squares_512.toml) against LAMMPS
# (../shared/peers/in.squares_pile.lmp with make_squares_pile.py 32 17, run unedited through
# bench/lammps/squares_pile_wrap.lmp), serially, one after the other: 512 squares settling under
# gravity 0.3 onto a floor, dt = 0.001. Prints the mobile body-steps per second of both codes
# (512 * steps / loop time), their ratio against the 3x target, whole-job wall times, and a sanity
# comparison of the settled piles (mean and max centre height of the 512 squares, final KE).
# See bench/README.md, "Polygons (issue 4)".
#
# Usage: bench/squares_vs_lammps.sh [-r REPEATS] [-s STEPS] [-k]
#   -r REPEATS  run each code REPEATS times, report the median timings (default 1)
#   -s STEPS    steps of both runs (default 60000, as the peer file)
#   -k          keep the work directory (printed at the end)
# Env: THREADS (granulab threads, default 1), PEER_DIR (folder of in.squares_pile.lmp and make_squares_pile.py; default <repo>/../shared/peers),
#      GRANULAB (binary; default <repo>/build/granulab), LMP (default lmp),
#      RESULTS_DIR (default <repo>/bench/results/<hostname>).
set -euo pipefail
THREADS=${THREADS:-1}  # granulab threads (run.threads); 1: the serial kernel

REPEATS=1 STEPS=60000 KEEP=0
while getopts "r:s:kh" opt; do
    case $opt in
        r) REPEATS=$OPTARG ;;
        s) STEPS=$OPTARG ;;
        k) KEEP=1 ;;
        h) sed -n '2,16p' "$0"; exit 0 ;;
        *) sed -n '2,16p' "$0" >&2; exit 2 ;;
    esac
done
for v in "$REPEATS" "$STEPS"; do
    [[ $v =~ ^[1-9][0-9]*$ ]] || { echo "error: options need positive integers (got '$v')" >&2; exit 2; }
done

ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
PEER_DIR=${PEER_DIR:-"$ROOT/../shared/peers"}
PEER="$PEER_DIR/in.squares_pile.lmp"
MAKE="$PEER_DIR/make_squares_pile.py"
WRAP="$ROOT/bench/lammps/squares_pile_wrap.lmp"
SCENE="$ROOT/examples/bench/squares_512.toml"
GRANULAB=${GRANULAB:-"$ROOT/build/granulab"}
LMP=${LMP:-lmp}
HOST=$(hostname)
RESULTS_DIR=${RESULTS_DIR:-"$ROOT/bench/results/$HOST"}

[[ -f $PEER && -f $MAKE ]] || { echo "error: peer input not found: $PEER, $MAKE (set PEER_DIR)" >&2; exit 1; }
[[ -x $GRANULAB ]] || { echo "error: granulab binary not found: $GRANULAB (build it with scripts/setup.sh, or set GRANULAB)" >&2; exit 1; }
command -v "$LMP" >/dev/null || { echo "error: LAMMPS executable '$LMP' not found (set LMP)" >&2; exit 1; }
if busy=$(pgrep -af 'granulab_tests|granulab_bench|granulab run|lmp -in|cc1plus' 2>/dev/null) && [[ -n $busy ]]; then
    echo "warning: other jobs are running; timings may be disturbed:" >&2
    echo "$busy" | cut -c1-120 >&2
fi

WORK=$(mktemp -d "${TMPDIR:-/tmp}/squares_vs_lammps.XXXXXX")
[[ $KEEP == 1 ]] || trap 'rm -rf "$WORK"' EXIT
T_END=$(python3 -c "print(f'{$STEPS * 0.001:.10g}')")

now() { date +%s.%N; }

echo "squares pile: 512 mobile squares (+ 32 frozen floor squares in LAMMPS), $STEPS steps of dt = 0.001, $REPEATS repeat(s)"
for ((k = 1; k <= REPEATS; ++k)); do
    d="$WORK/rep$k"
    mkdir -p "$d/lammps"
    echo "[$k/$REPEATS] LAMMPS ..." >&2
    (cd "$d/lammps" && python3 "$MAKE" 32 17) || { echo "error: $MAKE failed" >&2; exit 1; }
    t0=$(now)
    (cd "$d/lammps" && "$LMP" -in "$WRAP" -var peer "$PEER" -var dumpfile "$d/lammps/final.dump" \
        -var steps "$STEPS" -log "$d/lammps/log.lammps" -screen none) ||
        { echo "error: LAMMPS failed, see $d/lammps/log.lammps" >&2; KEEP=1; trap - EXIT; exit 1; }
    t1=$(now)
    echo "[$k/$REPEATS] granulab ..." >&2
    "$GRANULAB" run --threads "$THREADS" "$SCENE" --out "$d/granulab" --quiet --set "run.end_time=$T_END" ||
        { echo "error: granulab failed (output in $d/granulab)" >&2; KEEP=1; trap - EXIT; exit 1; }
    t2=$(now)
    echo "$t0 $t1 $t2" > "$d/walls.txt"
done

mkdir -p "$RESULTS_DIR"
python3 - "$WORK" "$REPEATS" "$STEPS" "$RESULTS_DIR/squares.csv" "$HOST" <<'EOF'
import csv, datetime, json, os, re, statistics, sys

work, reps, steps, csv_path, host = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5]
NMOB = 512

def lammps_log(path):
    text = open(path).read().splitlines()
    m = re.match(r"Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms",
                 [l for l in text if l.startswith("Loop time of")][-1])
    ver = next((l for l in text if l.startswith("LAMMPS (")), "LAMMPS (?)")
    return dict(loop=float(m.group(1)), steps=int(m.group(3)), atoms=int(m.group(4)), version=ver)

def lammps_dump(path):
    lines = open(path).read().splitlines()
    i = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[i].split()[2:]
    return [dict(zip(cols, map(float, l.split()))) for l in lines[i + 1:] if l.strip()]

L, G, wl, wg = [], [], [], []
for k in range(1, reps + 1):
    d = os.path.join(work, f"rep{k}")
    L.append(lammps_log(os.path.join(d, "lammps", "log.lammps")))
    G.append(json.load(open(os.path.join(d, "granulab", "summary.json"))))
    t0, t1, t2 = map(float, open(os.path.join(d, "walls.txt")).read().split())
    wl.append(t1 - t0); wg.append(t2 - t1)
med = statistics.median
d = os.path.join(work, f"rep{reps}")
ld = [r for r in lammps_dump(os.path.join(d, "lammps", "final.dump")) if r["y"] > 6.0]   # drop the frozen floor
with open(os.path.join(d, "granulab", "final.csv")) as f:
    gd = [{k: float(v) for k, v in r.items() if k in ("x", "y", "vx", "vy", "mass")} for r in csv.DictReader(f)]
lg, gs = L[-1], G[-1]
problems = []
if len(ld) != NMOB or gs["particles"] != NMOB:
    problems.append(f"body counts differ: expected {NMOB} mobile, LAMMPS {len(ld)}, granulab {gs['particles']}")
if lg["steps"] != steps or gs["steps"] != steps:
    problems.append(f"steps differ: LAMMPS {lg['steps']}, granulab {gs['steps']} (expected {steps})")

tl = med([NMOB * x["steps"] / x["loop"] for x in L])
tg = med([NMOB * x["steps"] / x["loop_time_s"] for x in G])
ratio = tg / tl
ke_l = sum(0.5 * (r["vx"] ** 2 + r["vy"] ** 2) for r in ld)          # mass 1
ke_g = gs["energy"]["kinetic"]
ymean_l = sum(r["y"] for r in ld) / len(ld); ymean_g = sum(r["y"] for r in gd) / len(gd)
ymax_l = max(r["y"] for r in ld); ymax_g = max(r["y"] for r in gd)
rel = lambda a, b: (a - b) / b
piles_ok = abs(rel(ymean_g, ymean_l)) < 0.05 and abs(rel(ymax_g, ymax_l)) < 0.05

w = 36
def row(name, a, b, r=None, fmt="{:.4g}"):
    ra = "" if r is None else f"{r:9.3f}"
    print(f"  {name:<{w}} {fmt.format(a):>13} {fmt.format(b):>13} {ra:>9}")

note = f" (median of {reps})" if reps > 1 else ""
print(f"LAMMPS: {lg['version']} (serial, {lg['atoms']} atoms, 512 mobile); granulab: {gs['version']} "
      f"({gs['integrator']}, {gs['broad_phase']})")
print(f"  {'quantity':<{w}} {'granulab':>13} {'LAMMPS':>13} {'g/L':>9}")
row(f"body-steps/s{note}", tg, tl, ratio, "{:.4e}")
row(f"loop time [s]{note}", med([x["loop_time_s"] for x in G]), med([x["loop"] for x in L]),
    med([x["loop_time_s"] for x in G]) / med([x["loop"] for x in L]), "{:.2f}")
row(f"whole job wall [s]{note}", med(wg), med(wl), med(wg) / med(wl), "{:.2f}")
row("final KE translational", ke_g, ke_l, ke_g / ke_l if ke_l else float("nan"))
row("mean centre height of the squares", ymean_g, ymean_l, ymean_g / ymean_l, "{:.3f}")
row("max centre height", ymax_g, ymax_l, ymax_g / ymax_l, "{:.3f}")
print(f"  granulab: {gs['contacts']} contacts + {gs['wall_contacts']} wall contacts at the end "
      f"({gs['contacts'] / NMOB:.2f} per square), {gs['neighbor_builds']} neighbour builds")
cf = gs.get("closest_feature")
if isinstance(cf, dict) and "tests_per_evaluation" in cf:
    print(f"  closest-feature work: {cf['tests_per_evaluation']:.2f} feature tests per tracked pair evaluation "
          f"(cold starts {100 * cf.get('cold_start_fraction', 0):.2f} %, full clips {100 * cf.get('full_clip_fraction', 0):.3f} %)")
print(f"verdict: granulab is {ratio:.2f}x LAMMPS in body-steps/s (target >= 3x: {'MET' if ratio >= 3 else 'NOT MET'}); "
      f"piles {'AGREE' if piles_ok else 'DIFFER'} within 5 % "
      f"(mean {100 * rel(ymean_g, ymean_l):+.2f} %, max {100 * rel(ymax_g, ymax_l):+.2f} %)")
for p in problems: print("problem:", p)

new = not os.path.exists(csv_path)
with open(csv_path, "a", newline="") as f:
    wr = csv.writer(f)
    if new:
        wr.writerow(["date", "host", "repeats", "steps", "granulab_body_steps_per_s", "lammps_body_steps_per_s",
                     "ratio_g_over_l", "granulab_job_s", "lammps_job_s", "ke_granulab", "ke_lammps",
                     "ymean_granulab", "ymean_lammps", "ymax_granulab", "ymax_lammps", "contacts_granulab"])
    wr.writerow([datetime.datetime.now().isoformat(timespec="seconds"), host, reps, steps, f"{tg:.6g}", f"{tl:.6g}",
                 f"{ratio:.4f}", f"{med(wg):.3f}", f"{med(wl):.3f}", f"{ke_g:.6g}", f"{ke_l:.6g}",
                 f"{ymean_g:.5f}", f"{ymean_l:.5f}", f"{ymax_g:.5f}", f"{ymax_l:.5f}", gs["contacts"]])
print(f"appended to {csv_path}")
EOF
[[ $KEEP == 1 ]] && echo "work directory kept: $WORK"
exit 0
