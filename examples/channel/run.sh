#!/usr/bin/env bash
# Particles in a 2D channel flow around a square obstacle: OpenFOAM computes the air flow
# (2 m x 0.5 m channel, 0.1 m square obstacle, inlet 2 m/s, laminar Re = 40), granulab blows
# small droplets through it (schiller_naumann drag, particles from an inlet on the left edge).
#
#   examples/channel/run.sh [--cells N] [--out DIR] [--cfd-only] [--no-plot] [-- GRANULAB_ARGS]
#
#   --cells N     cells along the obstacle's side (default 8: 20N x 5N - N^2 = 6336 cells;
#                 4 for a quick test)
#   --out DIR     output folder (default out/channel under the repository root)
#   --cfd-only    stop after OpenFOAM (blockMesh, icoFoam, foamToVTK, writeCellCentres)
#   --no-plot     skip plot_trajectories.py
#   -- ARGS       further arguments for `granulab run`, e.g. -- --set inlet[0].rate=100
#
# Steps: (a) source the OpenFOAM environment (Debian package "openfoam", OpenFOAM v1912);
# (b) copy case/ to DIR/case and set the resolution and time step; (c) blockMesh, icoFoam,
# foamToVTK, postProcess -func writeCellCentres -latestTime there (logs DIR/case/log.*);
# (d) granulab run particles.toml with the VTK series (DIR/granulab); (e) plot_trajectories.py
# -> DIR/trajectories.png. Timings go to DIR/timings.txt.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)

die() { echo "run.sh: error: $*" >&2; exit 1; }
# shellcheck source=../openfoam_case.sh
. "$here/../openfoam_case.sh"
usage() { sed -n '2,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }

cells=8
out=""
cfd_only=0
plot=1
extra=()
while [ $# -gt 0 ]; do
    case "$1" in
        --cells) [ $# -ge 2 ] || die "--cells needs a value"; cells=$2; shift 2 ;;
        --cells=*) cells=${1#*=}; shift ;;
        --out) [ $# -ge 2 ] || die "--out needs a value"; out=$2; shift 2 ;;
        --out=*) out=${1#*=}; shift ;;
        --cfd-only) cfd_only=1; shift ;;
        --no-plot) plot=0; shift ;;
        -h|--help) usage; exit 0 ;;
        --) shift; extra=("$@"); break ;;
        *) usage >&2; die "unknown argument '$1'" ;;
    esac
done
if ! { [[ "$cells" =~ ^[0-9]+$ ]] && [ "$cells" -ge 2 ] && [ "$cells" -le 100 ]; }; then
    die "--cells must be a whole number in [2, 100], got '$cells'"
fi
if [ -z "$out" ]; then out="$root/out/channel"; fi
out=$(realpath -m -- "$out")

# Time step: the largest of a list of values that divide the write interval (0.05 s) exactly,
# with dt <= 0.5 dx/4.5 m/s (OpenFOAM's Courant number adds |Ux|/dx and |Uy|/dy; the fastest
# air beside the obstacle is 3.4 m/s). N = 8: 0.00125 s, N = 4: 0.0025 s.
dt=$(of_time_step "$(awk -v n="$cells" 'BEGIN { print 0.5 * (0.1 / n) / 4.5 }')" \
    "0.025 0.0125 0.01 0.005 0.0025 0.002 0.00125 0.001 0.0005 0.00025 0.0002 0.000125 0.0001 0.00005")

# (a) OpenFOAM environment
of_environment blockMesh icoFoam foamToVTK postProcess

# (b) a fresh copy of the case
case_dir="$out/case"
of_fresh_case "$here/case" "$case_dir"
cat > "$case_dir/system/caseParameters" <<EOF
/*--------------------------------*- C++ -*----------------------------------*\\
  written by examples/channel/run.sh --cells $cells
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    location    "system";
    object      caseParameters;
}

n           $cells;     // cells along the obstacle's side D = 0.1 m
deltaT      $dt;     // [s] Courant number <= 0.5; divides writeInterval 0.05 s
nx0         $((4 * cells));     // 4n: cells in x over [0, 0.4]
nx2         $((15 * cells));     // 15n: cells in x over [0.5, 2]
ny0         $((2 * cells));     // 2n: cells in y over [0, 0.2] and over [0.3, 0.5]

// ************************************************************************* //
EOF

timings="$out/timings.txt"
echo "# step seconds (cells per obstacle side = $cells, deltaT = $dt s)" > "$timings"

# (c) mesh, flow, conversion to VTK
ncells=$((20 * cells * 5 * cells - cells * cells))
echo "OpenFOAM ($(command -v icoFoam)), $ncells cells ($cells per obstacle side), deltaT = $dt s, into $case_dir"
step blockMesh blockMesh
step icoFoam icoFoam
step foamToVTK foamToVTK
# cell centres of the last time (<time>/C, ASCII as controlDict's writeFormat) for the picture
step writeCellCentres postProcess -func writeCellCentres -latestTime
vtk="$case_dir/VTK"
series=$(find "$vtk" -maxdepth 1 -name '*.series' | head -n 1)
[ -n "$series" ] || die "foamToVTK wrote no .series index into $vtk"
echo "  VTK series: $series ($(find "$vtk" -maxdepth 1 -name '*.vtm' | wc -l) time steps)"
probe="$case_dir/postProcessing/wake/0/U"
if [ -f "$probe" ]; then
    awk '!/^#/ { t = $1; ux = $2; uy = $3 } END { gsub(/[()]/, "", ux);
        printf "  wake (0.8, 0.25) m: Ux = %.4f m/s, Uy = %.4f m/s at t = %s s\n", ux, uy, t }' "$probe"
fi
if [ "$cfd_only" = 1 ]; then
    echo "done (--cfd-only); timings in $timings"
    exit 0
fi

# (d) the particles in the flow
cd "$root"
[ -x build/granulab ] || die "build/granulab not found: build granulab first (scripts/setup.sh)"
echo "granulab: examples/channel/particles.toml into $out/granulab"
t0=$(now)
if ! build/granulab run examples/channel/particles.toml --set "fluid.fields=[\"$vtk\"]" \
        --out "$out/granulab" --overwrite ${extra[@]+"${extra[@]}"}; then
    die "granulab run failed (does this build know the [fluid] section?)"
fi
t1=$(now)
echo "granulab $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')" >> "$timings"

# (e) the picture: trajectories over the air speed at the last time
if [ "$plot" = 1 ]; then
    t0=$(now)
    /usr/bin/python3 examples/channel/plot_trajectories.py "$out" || die "plot_trajectories.py failed"
    t1=$(now)
    echo "plot $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')" >> "$timings"
    echo "picture: $out/trajectories.png"
fi
echo "done: $out/granulab (view: paraview $out/granulab/snapshots.pvd, with $series for the air);"
echo "      timings in $timings"
