#!/bin/sh
# SPDX-License-Identifier: MIT
# `mpirun -np P granulab run` of an edmd scene against the serial run (issue 15; edmd spec 5.7
# AT-4/AT-5): a cooling 2D gas that clusters (eps = 0.5, TC model, cluster statistics on) with
# an elastic pre-run ended by a collision count.
#   - 2 and 3 ranks: final.csv identical to the serial run's (runs on several ranks take the
#     serial grid): the same collisions in the same order; series.csv identical in every column (Haff's law, collision
#     frequency, kurtosis, density quantiles, cluster counts and moments) except the summed
#     accumulators (dissipated energy, pressure: per-rank partial sums, equal to round-off).
#   - checkpoints do not depend on the rank count: a run checkpointed on 4 ranks resumes on 1, 2
#     and 3 ranks, and each ends exactly where the uninterrupted serial run ends.
#   - a serial run's checkpoint continues on 2 ranks, and a serial run's on a power-of-two grid
#     (edmd.cell_grid = "morton") on 2 ranks: both end exactly where the serial run ends.
#   - a checksum over ids: every id once in every final.csv.
#   - a longer clustering run on 2 ranks, in which records arrive late and are applied as at
#     their time, still ends with the serial final.csv.
#   - an inelastic collapse stops every rank with the diagnosis (exit status 3); growing spheres
#     are refused on several ranks (exit status 2).
# Usage: parallel_run.sh GRANULAB SCENE WORKDIR MPIEXEC [MPI flags ...]
set -eu
granulab=$1 scene=$2 work=$3 mpiexec=$4
shift 4
on_ranks() { np=$1; shift; "$mpiexec" -np "$np" "$@"; }
flags="$*"
rm -rf "$work"
mkdir -p "$work"
common="--set edmd.count=2000 --set edmd.equilibrate=20 --set edmd.clusters=true --set edmd.series_points=12 -q"

"$granulab" run "$scene" $common --set edmd.end_tau=3 --out "$work/serial"
"$granulab" run "$scene" $common --set edmd.cell_grid=morton --set edmd.end_tau=3 --out "$work/serialm"
for np in 2 3; do
    on_ranks $np $flags "$granulab" run "$scene" $common --set edmd.end_tau=3 --out "$work/np$np"
done
# Checkpointed on 4 ranks at tau = 1.5, resumed on 1, 2 and 3 ranks to tau = 3.
on_ranks 4 $flags "$granulab" run "$scene" $common --set edmd.end_tau=1.5 --out "$work/first4"
"$granulab" run "$scene" $common --set edmd.end_tau=3 --resume "$work/first4" --out "$work/resume1"
for np in 2 3; do
    on_ranks $np $flags "$granulab" run "$scene" $common --set edmd.end_tau=3 --resume "$work/first4" \
        --out "$work/resume$np"
done

# Serial checkpoints continued on 2 ranks, on the default grid and on the power-of-two grid.
"$granulab" run "$scene" $common --set edmd.end_tau=1.5 --out "$work/free1"
on_ranks 2 $flags "$granulab" run "$scene" $common --set edmd.end_tau=3 --resume "$work/free1" --out "$work/free2"
"$granulab" run "$scene" $common --set edmd.cell_grid=morton --set edmd.end_tau=1.5 --out "$work/morton1"
on_ranks 2 $flags "$granulab" run "$scene" $common --set edmd.cell_grid=morton --set edmd.end_tau=3 \
    --resume "$work/morton1" --out "$work/morton2"

# A longer cooling run on 2 ranks (1e4 disks per rank, clustered by tau = 200) in which records
# arrive late and are applied as at their time (Engine::receive): still the serial result.
long="--set edmd.count=20000 --set edmd.equilibrate=5 --set edmd.series_points=5 -q --set edmd.end_tau=200"
"$granulab" run "$scene" $long --out "$work/long1"
on_ranks 2 $flags "$granulab" run "$scene" $long --out "$work/long2"

# What the parallel engine does not run is refused with exit status 2 and the key.
for bad in "edmd.growth_rate=0.001"; do
    status=0
    on_ranks 2 $flags "$granulab" run "$scene" $common --set "$bad" --out "$work/refused" 2>"$work/refused.log" ||
        status=$?
    if [ "$status" -ne 2 ] || ! grep -q "${bad%%=*}" "$work/refused.log"; then
        echo "FAIL: --set $bad on 2 ranks ended with status $status:"
        cat "$work/refused.log"
        exit 1
    fi
done

# An inelastic collapse (a disk bouncing to rest on a floor without the TC model) stops on 2
# ranks with the watchdog's diagnosis and exit status 3, as in a serial run, instead of hanging.
status=0
on_ranks 2 $flags "$granulab" run "$(dirname "$0")/../data/zeno_bounce.toml" -q --out "$work/zeno" 2>"$work/zeno.log" || status=$?
if [ "$status" -ne 3 ] || ! grep -q "inelastic collapse" "$work/zeno.log"; then
    echo "FAIL: the collapse on 2 ranks ended with status $status:"
    cat "$work/zeno.log"
    exit 1
fi

python3 - "$work" <<'PY'
import csv, json, math, sys
work = sys.argv[1]
def rows(path):
    with open(path) as f:
        return list(csv.reader(f))
failures = []
serial_final = rows(f"{work}/serial/final.csv")
ids = sorted(int(r[0]) for r in serial_final[1:] if r and not r[0].startswith("#"))
serial_morton = rows(f"{work}/serialm/final.csv")
for run in ["np2", "np3", "resume1", "resume2", "resume3", "free2", "morton2"]:
    final = rows(f"{work}/{run}/final.csv")
    if final != (serial_morton if run == "morton2" else serial_final):
        failures.append(f"{run}/final.csv differs from the serial run's")
    got = sorted(int(r[0]) for r in final[1:] if r and not r[0].startswith("#"))
    if got != ids or len(set(got)) != 2000:
        failures.append(f"{run}/final.csv: ids lost or duplicated")
serial = rows(f"{work}/serial/series.csv")
header = serial[0]
summed = {"dissipated_energy", "pressure", "reduced_pressure", "total_energy"}
for run in ["np2", "np3"]:
    series = rows(f"{work}/{run}/series.csv")
    if len(series) != len(serial) or series[0] != header:
        failures.append(f"{run}/series.csv: {len(series)} rows, serial {len(serial)}")
        continue
    for k, (a, b) in enumerate(zip(serial[1:], series[1:])):
        for name, x, y in zip(header, a, b):
            if x == y:
                continue
            if name in summed:
                fx, fy = float(x), float(y)
                if not (fx == fy or abs(fx - fy) <= 1e-12 * max(abs(fx), abs(fy))):
                    failures.append(f"{run} row {k} {name}: {x} vs {y}")
            else:
                failures.append(f"{run} row {k} {name}: {x} vs {y}")
    summary = json.load(open(f"{work}/{run}/summary.json"))
    per_rank = summary.get("parallel", {}).get("per_rank", [])
    if len(per_rank) != int(run[2:]):
        failures.append(f"{run}/summary.json: per-rank figures missing")
    elif sum(r["particles"] for r in per_rank) != 2000:
        failures.append(f"{run}/summary.json: the ranks own {sum(r['particles'] for r in per_rank)} particles")
if rows(f"{work}/long2/final.csv") != rows(f"{work}/long1/final.csv"):
    failures.append("long2/final.csv differs from the serial run's")
late = sum(r["late_records_applied"] for r in json.load(open(f"{work}/long2/summary.json"))["parallel"]["per_rank"])
if late == 0:
    failures.append("long2: no late record was applied (the run no longer tests that path)")
reclaimed = sum(r["slots_reclaimed"] for r in json.load(open(f"{work}/long2/summary.json"))["parallel"]["per_rank"])
if reclaimed == 0:
    failures.append("long2: no dead slot was reclaimed (the run no longer tests that path)")
# Haff's law holds in the parallel run as in the serial one (homogeneous cooling before tau ~ 1).
for k, row in enumerate(rows(f"{work}/np3/series.csv")[1:]):
    r = dict(zip(header, row))
    if 0 < float(r["tau"]) <= 1 and abs(float(r["temperature"]) / float(r["temperature_haff"]) - 1) > 0.1:
        failures.append(f"np3 row {k}: T/T_Haff = {float(r['temperature']) / float(r['temperature_haff']):.3f}")
for f in failures[:20]:
    print("FAIL:", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
PY
