#!/usr/bin/env bash
# Levitation of a polystyrene ball in a vertical air stream (cfddem spec section 7, T6):
# OpenFOAM computes the air flow in a 6 m x 6 m vertical channel, granulab moves the ball in it.
#
#   examples/levitation/run.sh [--cells N] [--out DIR] [--radius R] [--cfd-only] [-- GRANULAB_ARGS]
#
#   --cells N     cells per side of the square mesh (default 60; 20 for a quick test)
#   --out DIR     output folder (default out/levitation under the repository root)
#   --radius R    ball radius [m] (default: ball.toml's 0.02); e.g. 0.0204 or 0.021
#   --cfd-only    stop after OpenFOAM (blockMesh, icoFoam, foamToVTK)
#   -- ARGS       further arguments for `granulab run`, e.g. -- --set dem.dt=2e-4
#
# Steps: (a) source the OpenFOAM environment (Debian package "openfoam", OpenFOAM v1912);
# (b) copy case/ to DIR/case and set the resolution and time step; (c) blockMesh, icoFoam,
# foamToVTK there (logs DIR/case/log.*); (d) granulab run ball.toml with the VTK series
# (DIR/granulab); (e) plot.py -> DIR/levitation.png. Timings go to DIR/timings.txt.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)

die() { echo "run.sh: error: $*" >&2; exit 1; }
# shellcheck source=../openfoam_case.sh
. "$here/../openfoam_case.sh"
usage() { sed -n '2,17p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }

cells=60
out=""
radius=""
cfd_only=0
extra=()
while [ $# -gt 0 ]; do
    case "$1" in
        --cells) [ $# -ge 2 ] || die "--cells needs a value"; cells=$2; shift 2 ;;
        --cells=*) cells=${1#*=}; shift ;;
        --out) [ $# -ge 2 ] || die "--out needs a value"; out=$2; shift 2 ;;
        --out=*) out=${1#*=}; shift ;;
        --radius) [ $# -ge 2 ] || die "--radius needs a value"; radius=$2; shift 2 ;;
        --radius=*) radius=${1#*=}; shift ;;
        --cfd-only) cfd_only=1; shift ;;
        -h|--help) usage; exit 0 ;;
        --) shift; extra=("$@"); break ;;
        *) usage >&2; die "unknown argument '$1'" ;;
    esac
done
if ! { [[ "$cells" =~ ^[0-9]+$ ]] && [ "$cells" -ge 4 ] && [ "$cells" -le 1000 ]; }; then
    die "--cells must be a whole number in [4, 1000], got '$cells'"
fi
# --out relative to the caller's folder; the default relative to the repository root
if [ -z "$out" ]; then out="$root/out/levitation"; fi
out=$(realpath -m -- "$out")

# Time step: the largest of a list of values that divide the write interval (0.1 s) exactly
# with Courant number U dt/dx <= 0.5 at U = 4.5 m/s (the fastest air, near the walls, is
# 3.9 m/s): dt <= 0.5 (6/cells)/4.5. 60 cells: 0.01 s, 30: 0.02 s, 20: 0.025 s.
dt=$(of_time_step "$(awk -v n="$cells" 'BEGIN { print 0.5 * (6.0 / n) / 4.5 }')" \
    "0.05 0.025 0.02 0.0125 0.01 0.005 0.004 0.0025 0.002 0.00125 0.001 0.0005 0.0004 0.00025 0.0002 0.0001")

# (a) OpenFOAM environment
of_environment blockMesh icoFoam foamToVTK

# (b) a fresh copy of the case
case_dir="$out/case"
of_fresh_case "$here/case" "$case_dir"
cat > "$case_dir/system/caseParameters" <<EOF
/*--------------------------------*- C++ -*----------------------------------*\\
  written by examples/levitation/run.sh --cells $cells
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    location    "system";
    object      caseParameters;
}

cells       $cells;     // cells per side of the 6 m x 6 m square
deltaT      $dt;     // [s] Courant number <= 0.5 at 4.5 m/s; divides writeInterval 0.1 s

// ************************************************************************* //
EOF

timings="$out/timings.txt"
echo "# step seconds (cells = $cells, deltaT = $dt s)" > "$timings"

# (c) mesh, flow, conversion to VTK
echo "OpenFOAM ($(command -v icoFoam)), $cells x $cells cells, deltaT = $dt s, into $case_dir"
step blockMesh blockMesh
step icoFoam icoFoam
step foamToVTK foamToVTK
vtk="$case_dir/VTK"
series=$(find "$vtk" -maxdepth 1 -name '*.series' | head -n 1)
[ -n "$series" ] || die "foamToVTK wrote no .series index into $vtk"
echo "  VTK series: $series ($(find "$vtk" -maxdepth 1 -name '*.vtm' | wc -l) time steps)"
probe="$case_dir/postProcessing/centreline/0/U"
if [ -f "$probe" ]; then
    # the air speed on the centreline at the ball's start height (probe 1: x = 3, y = 3 m)
    awk '!/^#/ { t = $1; u = $6 } END { printf "  centreline air speed at (3, 3) m: %.4f m/s at t = %s s\n", u, t }' "$probe"
fi
if [ "$cfd_only" = 1 ]; then
    echo "done (--cfd-only); timings in $timings"
    exit 0
fi

# (d) the ball in the flow
cd "$root"
[ -x build/granulab ] || die "build/granulab not found: build granulab first (scripts/setup.sh)"
set_radius=()
if [ -n "$radius" ]; then set_radius=(--set "particle[0].radius=$radius"); fi
echo "granulab: examples/levitation/ball.toml into $out/granulab"
t0=$(now)
if ! build/granulab run examples/levitation/ball.toml --set "fluid.fields=[\"$vtk\"]" \
        ${set_radius[@]+"${set_radius[@]}"} --out "$out/granulab" --overwrite \
        ${extra[@]+"${extra[@]}"}; then
    die "granulab run failed (does this build know the [fluid] section and output.particle_series?)"
fi
t1=$(now)
echo "granulab $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')" >> "$timings"

# (e) the plot
plot_args=()
if [ -n "$radius" ]; then plot_args=(--radius "$radius"); fi
/usr/bin/python3 examples/levitation/plot.py "$out" ${plot_args[@]+"${plot_args[@]}"} ||
    die "plot.py failed"
echo "done: $out/levitation.png; timings in $timings"
