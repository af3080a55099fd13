#!/usr/bin/env bash
# The cohesive draining crater of gc2d spec 8.8 (Schinner Sec. 4.4): a k_coh sweep over the
# monodisperse (regular 15-gons) and polydisperse (r in [0.75 r, 1.25 r]) series, the clogging
# run with cohesion switched off by a [[change]], granulab analyze on every run (repose by the
# integral method over the residual slopes A and B, coordination, contact persistence in region
# C, roughness), the plots, and the measured figures against the thesis (summarize.py).
# One simulation after the other (never two at once: the timings in README.md are single-core).
#   examples/studies/crater/run.sh            # full size: box 180 d (many hours, README.md)
#   examples/studies/crater/run.sh reduced    # box 40 d, outlet 16 d (~10 min CPU)
#   KCOH="0 1e5 2e5" examples/studies/crater/run.sh reduced   # another sweep [N/m]
#   SERIES=mono examples/studies/crater/run.sh reduced        # one series only (mono | poly)
# Run from the repository root after building build/granulab. OUT (default out/crater) holds the
# runs; PYTHON (default: python3 with numpy and matplotlib, else /usr/bin/python3) plots.
set -euo pipefail
MODE=${1:-full}
OUT=${OUT:-out/crater}
KCOH=${KCOH:-0 0.5e5 1e5 1.5e5 2e5 2.5e5 3e5}
SERIES=${SERIES:-mono poly}
G=build/granulab
S=examples/studies/crater
if [[ -z "${PYTHON:-}" ]]; then
  PYTHON=python3
  "$PYTHON" -c 'import matplotlib, numpy' 2>/dev/null || PYTHON=/usr/bin/python3
fi
case $MODE in
  reduced)
    SUFFIX=_reduced
    HALF=0.06  # [m] box half width (40 d)
    HOLE=0.024 # [m] outlet half width (16 d)
    TOP=0.1    # [m] above the fill
    ;;
  full)
    SUFFIX=
    HALF=0.27  # [m] 180 d
    HOLE=0.045 # [m] 30 d (the clogging scene clog.toml: 16 d)
    TOP=0.3
    ;;
  *)
    echo "usage: $0 [full|reduced]" >&2
    exit 2
    ;;
esac
mkdir -p "$OUT"
RUNS=()

run() { # name scene [--set ...]
  local name=$1 scene=$2
  shift 2
  echo "== $name: $G run $S/$scene $*"
  /usr/bin/time -f "   %U s CPU, %e s wall" "$G" run "$S/$scene" --out "$OUT/$name" --overwrite -q "$@"
  RUNS+=("$OUT/$name")
}

# The time the outlet opens: the persistence reference (a snapshot falls on it).
open_at() { sed -n '/^\[\[outlet\]\]/,/^$/s/^open_at *= *\([0-9.e+-]*\).*/\1/p' "$S/$1" | head -1; }

analyze() { # dir scene outlet-half-width
  local dir=$1 scene=$2 hole=$3
  local a="-$HALF:-$hole" b="$hole:$HALF"
  # Regions A and B: the residual slopes between the side walls and the outlet's edges (the
  # integral repose of each range goes to repose_profile.csv's notes repose_range_1/2_deg).
  "$G" analyze "$dir" repose roughness --range "$a" --range "$b" -q
  "$G" analyze "$dir" coordination --region "-$HALF:$HALF,0:$TOP" -q
  # Region C: the grains above the outlet at the end (the crater floor or the plug); the pile
  # that the thesis collects below the box is removed by the outlet here (README.md).
  "$G" analyze "$dir" persistence --reference "$(open_at "$scene")" --region "-$hole:$hole,0:$TOP" -q
  local snap
  snap=$(ls -d "$dir"/analysis/snapshot_* | tail -1)
  "$PYTHON" scripts/plot_analysis.py "$snap" >/dev/null || echo "plot_analysis failed for $snap"
}

for series in $SERIES; do
  for k in $KCOH; do
    run "${series}_k$k" "$series$SUFFIX.toml" --set contact[0].cohesion="$k"
    analyze "$OUT/${series}_k$k" "$series$SUFFIX.toml" "$HOLE"
  done
done
# Clogging at k_coh > 2e5 N/m with a 16 d outlet, then cohesion 0 by the scene's [[change]].
run clog "clog$SUFFIX.toml"
analyze "$OUT/clog" "clog$SUFFIX.toml" 0.024

echo
echo "== measured (last snapshot of each run; $S/summarize.py explains each figure)"
"$PYTHON" "$S/summarize.py" "${RUNS[@]}"
cat <<'TXT'

== thesis (gc2d spec 8.8)
repose (A, B, integral method): 22-23 deg (dry, Hornbaker) for k_coh < 0.5e5 N/m, ~linear in
                                k_coh from 0.5e5 to 2.5e5 N/m
clogging          : k_coh > 2e5 N/m and an outlet of 15-20 d clogs easily (grains stick even to
                    the underside of the box); k_coh = 0 restarts the flow; 20-25 d never clogged
coordination      : ~4 for monodisperse grains; grows with k_coh for polydisperse ones
persistence (C)   : 4-5 times more initial neighbour pairs survive than without cohesion
roughness         : grows at all wavelengths with k_coh, most at small wavenumbers
region C          : shallower than A and B, rugged at high cohesion
TXT
