#!/bin/sh
# SPDX-License-Identifier: MIT
# `mpirun -np P granulab run` of dem scenes against the serial run (issue 16; docs/physics/dem-mpi.md).
# The slab decomposition adds a particle's contact forces in its rank's list order, so runs on
# different rank counts agree to round-off; the chaos of a flowing granular medium then amplifies
# it (measured on the poured disks of examples/disks_in_box.toml: ~1e-16 relative until the first
# dense impacts, then x10 every ~3 ms). So the comparisons against the serial run are made where
# every grain has contacts and round-off stays small:
#   - a settled bed of 900 disks (examples/bench/disk_bed.toml at 30 x 30, Verlet, walls, 1500
#     contacts, checkpointed by a serial run at t = 3 s): continued 0.5 s on 1, 2 and 3 ranks,
#     every particle within 1e-10 m of the serial run's position (measured 3e-13 m; radius
#     0.5 m) and 1e-8 m/s, rad/s of its velocities (measured 6e-11); every id once. Dropping the
#     ghosts' drift velocities from the halo moves grains by 0.5 m here;
#   - a heap of 400 heptagons (examples/sand_heap.toml, Gear, overlap-area law), checkpointed
#     serially at t = 0.1 s and continued 0.01 s on 3 ranks: positions within 1e-10 m (measured
#     2e-13 m), velocities within 1e-5 (measured 4e-7: the area law's cancellation);
#   - the same rank count twice: series.csv and final.csv byte for byte (determinism), also
#     with load balancing off;
#   - checkpoints do not depend on the rank count: the bed checkpointed on 3 ranks at 3.25 s
#     and resumed on 3 ranks ends byte for byte as the uninterrupted 3-rank run; resumed on 1
#     and 2 ranks, within the bounds above;
#   - particles in and out: a hopper fed by an inlet and drained by an outlet
#     (examples/machines/hopper_inlet.toml, 200 emitted, ~150 removed by t = 0.5 s) on 2 and 3
#     ranks, and a pile fed by a REL drop source (pile_dropsource.toml) to t = 0.12 s on 2 ranks:
#     the same particles (ids) within the bounds above, the same flow counters in summary.json;
#   - the iterating predictor-corrector (every rank iterates until all accept, the ghosts follow
#     each iteration): the bed settled with it serially to t = 2 s and continued 0.3 s on 2 ranks,
#     within the bounds above; a pull spring on a grain of the bed (the rank that owns the grain
#     pulls it), 0.3 s from the start on 2 ranks against one (the bed still falls and collides:
#     velocities within 1e-7, measured 6e-9; positions 1e-11 m);
#   - a fluid (uniform upward flow, Stokes drag, buoyancy) and mutual attraction within a cutoff
#     of 4 m, three times the contacts' halo: the bed 0.3 s from the start on 2 ranks against one
#     (measured 0 and 3e-13 m; a halo that ignores the cutoff moves grains 0.13 m); the fluid's
#     series columns (drag, Reynolds number, voidage) within 1e-10 relative;
#   - what reaches beyond the ghost layer: the di_felice drag, whose voidage cells (4.4 m) gather
#     every rank's particles, 0.3 s, and attraction between all pairs, 0.1 s, on 2 ranks against
#     one (measured 2e-13 and 4e-15 m; voidage cells of one rank's particles only: 0.28 m).
# Usage: parallel_dem_run.sh GRANULAB EXAMPLES_DIR WORKDIR MPIEXEC [MPI flags ...]
set -eu
granulab=$1 examples=$2 work=$3 mpiexec=$4
shift 4
flags="$*"
on_ranks() { np=$1; shift; "$mpiexec" -np "$np" $flags "$@"; }
rm -rf "$work"
mkdir -p "$work"
bed="$examples/bench/disk_bed.toml"
heap="$examples/sand_heap.toml"
common="-q --threads 1 --set output.vtk=false"
small="$common --set block[0].region=[0.1,0.0,33.9,29.1] --set run.benchmark_from=-1 \
    --set wall[0].points=[[0.0,60.0],[0.0,0.0],[34.16,0.0],[34.16,60.0]] --set output.series_interval=0.05"

"$granulab" run "$bed" $small --set run.end_time=3.0 --out "$work/settled"
continued() {  # continued NAME NP END [options]: the settled bed resumed on NP ranks
    name=$1 np=$2 end=$3
    shift 3
    cp -r "$work/settled" "$work/$name"
    on_ranks $np "$granulab" run "$bed" $small --set run.end_time=$end "$@" --resume "$work/$name"
}
cp -r "$work/settled" "$work/bed"
"$granulab" run "$bed" $small --set run.end_time=3.5 --resume "$work/bed"
for np in 1 2 3; do continued bed$np $np 3.5; done
continued bed2again 2 3.5
continued bed2flat 2 3.5 --set run.load_balance=false
continued bed2flatagain 2 3.5 --set run.load_balance=false
# Checkpointed on 3 ranks at 3.25 s, resumed on 3, 2 and 1 ranks to 3.5 s.
continued whole3 3 3.5 --set output.checkpoint_interval=0.25
continued first3 3 3.25
for np in 1 2 3; do
    cp -r "$work/first3" "$work/resume$np"
    on_ranks $np "$granulab" run "$bed" $small --set run.end_time=3.5 --set output.checkpoint_interval=0.25 \
        --resume "$work/resume$np"
done

"$granulab" run "$heap" $common --set output.series_interval=0.01 --set run.end_time=0.1 --out "$work/heap"
cp -r "$work/heap" "$work/heap3"
on_ranks 3 "$granulab" run "$heap" $common --set output.series_interval=0.01 --set run.end_time=0.11 \
    --resume "$work/heap3"
"$granulab" run "$heap" $common --set output.series_interval=0.01 --set run.end_time=0.11 --resume "$work/heap"

# Particles in and out.
hopper="$examples/machines/hopper_inlet.toml"
pile="$examples/machines/pile_dropsource.toml"
"$granulab" run "$hopper" $common --set run.end_time=0.5 --out "$work/hopper1"
for np in 2 3; do
    on_ranks $np "$granulab" run "$hopper" $common --set run.end_time=0.5 --out "$work/hopper$np"
done
"$granulab" run "$pile" $common --set run.end_time=0.12 --out "$work/pile1"
on_ranks 2 "$granulab" run "$pile" $common --set run.end_time=0.12 --out "$work/pile2"

# The iterating predictor-corrector, and a pull spring.
pc="$small --set dem.integrator=\"pc\" --set dem.pc_iterations=3"
"$granulab" run "$bed" $pc --set run.end_time=2.0 --out "$work/pcsettled"
cp -r "$work/pcsettled" "$work/pc1"
cp -r "$work/pcsettled" "$work/pc2"
"$granulab" run "$bed" $pc --set run.end_time=2.3 --resume "$work/pc1"
on_ranks 2 "$granulab" run "$bed" $pc --set run.end_time=2.3 --resume "$work/pc2"
# The bed with one more section, 0.3 s from the start on one rank (NAME1) and on 2 (NAME2).
bed_with() {  # bed_with NAME SECTION-TEXT [options]
    name=$1 section=$2
    shift 2
    cp "$bed" "$work/$name.toml"
    printf '%b' "$section" >>"$work/$name.toml"
    "$granulab" run "$work/$name.toml" $small --set run.end_time=0.3 "$@" --out "$work/${name}1"
    on_ranks 2 "$granulab" run "$work/$name.toml" $small --set run.end_time=0.3 "$@" --out "$work/${name}2"
}
bed_with spring '\n[[spring]]\nparticle = 100\nk = 200.0\npull_start = [20.0, 4.0]\nspeed = 5.0\n'

# A fluid and mutual attraction within a cutoff.
bed_with fluid '\n[fluid]\ndensity = 1.0\nviscosity = 0.05\ndrag = "stokes"\nvelocity = [1.0, 5.0]\n' \
    --set dem.mass_model=\"sphere\"
bed_with attraction '\n[attraction]\nconstant = 5.0\ncutoff = 4.0\n'
# What reaches beyond the ghost layer: the di_felice voidage cells (4.4 m, across the cut) and
# attraction between all pairs (0.1 s: 900^2 pairs a step).
bed_with voidage '\n[fluid]\ndensity = 1.0\nviscosity = 0.05\ndrag = "di_felice"\nvelocity = [1.0, 5.0]\n' \
    --set dem.mass_model=\"sphere\"
bed_with allpairs '\n[attraction]\nconstant = 5.0\n' --set run.end_time=0.1

python3 - "$work" <<'PY'
import csv, sys
work = sys.argv[1]
failures = []

def rows(path):
    with open(path) as f:
        return [r for r in csv.reader(f) if r and not r[0].startswith("#")]

def by_id(path):
    table = rows(path)
    head = table[0]
    return head, {int(r[0]): r for r in table[1:]}

def close(ref, run, dx=1e-10, dv=1e-8):
    head, a = by_id(f"{work}/{ref}/final.csv")
    _, b = by_id(f"{work}/{run}/final.csv")
    if sorted(a) != sorted(b):
        failures.append(f"{run}/final.csv: ids differ from {ref} ({len(b)} against {len(a)})")
        return
    col = {name: k for k, name in enumerate(head)}
    worst = [0.0, 0.0]
    for i, ra in a.items():
        rb = b[i]
        for name in ("x", "y"):
            worst[0] = max(worst[0], abs(float(ra[col[name]]) - float(rb[col[name]])))
        for name in ("vx", "vy", "omega"):
            worst[1] = max(worst[1], abs(float(ra[col[name]]) - float(rb[col[name]])))
    if not (worst[0] <= dx and worst[1] <= dv):
        failures.append(f"{run} against {ref}: largest position difference {worst[0]:.3g} m (bound {dx}), "
                        f"velocity {worst[1]:.3g} m/s (bound {dv})")
    series_close(ref, run)

def series_close(ref, run):
    a, b = rows(f"{work}/{ref}/series.csv"), rows(f"{work}/{run}/series.csv")
    if len(a) != len(b) or a[0] != b[0]:
        failures.append(f"{run}/series.csv: {len(b)} rows or columns differ from {ref} ({len(a)})")
        return
    head = a[0]
    for name in ("kinetic_energy", "potential_energy", "total_energy"):
        k = head.index(name)
        for ra, rb in zip(a[1:], b[1:]):
            x, y = float(ra[k]), float(rb[k])
            if abs(x - y) > 1e-8 * max(abs(x), abs(y)):
                failures.append(f"{run}/series.csv t = {ra[0]}: {name} {y} against {x} ({ref})")
                break
    # The fluid's statistics: the ranks' own evaluations, reduced (not the output copy's).
    for k in (k for k, name in enumerate(head) if name.startswith("fluid_")):
        for ra, rb in zip(a[1:], b[1:]):
            x, y = float(ra[k]), float(rb[k])
            if abs(x - y) > 1e-10 * max(abs(x), abs(y)):
                failures.append(f"{run}/series.csv t = {ra[0]}: {head[k]} {y} against {x} ({ref})")
                break

def same(ref, run):
    for name in ("final.csv", "series.csv"):
        if open(f"{work}/{ref}/{name}", "rb").read() != open(f"{work}/{run}/{name}", "rb").read():
            failures.append(f"{run}/{name} is not byte for byte {ref}/{name}")

for run in ("bed1", "bed2", "bed3", "bed2flat"):
    close("bed", run)
for run in ("resume1", "resume2"):
    close("whole3", run)
close("heap", "heap3", dv=1e-5)
for run in ("hopper2", "hopper3"):
    close("hopper1", run)
close("pile1", "pile2")
close("pc1", "pc2")
close("spring1", "spring2", dv=1e-7)  # the bed still falls and collides: measured 6e-9
close("fluid1", "fluid2")
close("attraction1", "attraction2")
close("voidage1", "voidage2")
close("allpairs1", "allpairs2")
import json
for ref, run in (("hopper1", "hopper2"), ("hopper1", "hopper3"), ("pile1", "pile2")):
    a = json.load(open(f"{work}/{ref}/summary.json"))["flow"]
    b = json.load(open(f"{work}/{run}/summary.json"))["flow"]
    for key in ("inserted", "removed", "skipped", "sources", "inlets"):
        if a[key] != b[key]:
            failures.append(f"{run} flow {key}: {b[key]} against {a[key]}")
    for key in ("mass_in", "mass_out"):
        if abs(a[key] - b[key]) > 1e-12 * max(abs(a[key]), 1e-300):
            failures.append(f"{run} flow {key}: {b[key]} against {a[key]}")
same("bed2", "bed2again")
same("bed2flat", "bed2flatagain")
same("whole3", "resume3")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("dem on 1, 2, 3 ranks: serial results to round-off, deterministic, checkpoints across rank counts")
PY
