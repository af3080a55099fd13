#!/usr/bin/env bash
# The perturbed piles of gc2d spec 8.7 (Schinner Sec. 4.3): pour and save a pile (pile.toml),
# then resume copies of it with a changed scene, one simulation after the other:
#   tap_<T>   the whole floor taps at 20 Hz, amplitude 0.1 mm (vib_type = "tapping"), for T s,
#             then rests 0.2 s                                            (Sec. 4.3.1)
#   stamp_down, stamp_up   the floor stamp moves at 1 mm/s out of / into the pile; p(u) from
#             series.csv (stamp_curve.py)                                 (Sec. 4.3.2)
#   elastic   g lowered linearly from 9.81 to 2.45e-3 m/s^2, then rests; strain and elastic
#             constants between the loaded and the unloaded pile           (Sec. 4.3.3)
# and summarize.py prints the measured figures against the thesis.
#   examples/studies/perturb/run.sh            # thesis size: 2,500 grains (about 3 h, README.md)
#   examples/studies/perturb/run.sh medium     # 600 grains (about 20 min CPU)
#   examples/studies/perturb/run.sh reduced    # 200 grains, the CI test's size (about 1 min CPU)
# REUSE_PILE=1 keeps an earlier OUT/pile of the same mode and runs the perturbations only.
# Run from the repository root after building build/granulab. OUT (default out/perturb) holds
# the runs; PYTHON (default: python3 with matplotlib, else /usr/bin/python3) plots.
set -euo pipefail
MODE=${1:-full}
OUT=${OUT:-out/perturb}
G=build/granulab
S=examples/studies/perturb
SCENE=$S/pile.toml
if [[ -z "${PYTHON:-}" ]]; then
  PYTHON=python3
  "$PYTHON" -c 'import matplotlib, numpy' 2>/dev/null || PYTHON=/usr/bin/python3
fi

stamp() {  # half width [m]: the floor in three pieces around a stamp at x = 0
  local h=$1
  echo "wall[0].points=[[-0.4,0.0],[-$h,0.0]] wall[1].points=[[-$h,0.0],[$h,0.0]]" \
       "wall[2].points=[[$h,0.0],[0.4,0.0]]"
}
case $MODE in
  full)    # the thesis: 2,501 drops in 25 s, 1 s to settle, dt 2e-6 s, the 4.5 cm stamp
    PILE=(); HALF=0.0225; T0=26.0; SNAP=1.0; TAPS="0.5 1.0 2.0"; SWEEP=1.0; TG=1.0; WIN=() ;;
  medium)  # 601 drops in 6 s, 2 s to settle, dt 5e-6 s, the thesis' 4.5 cm stamp
    PILE=(source[0].to=6.0 run.end_time=8.0 dem.dt=5e-6); HALF=0.0225; T0=8.0; SNAP=0.5; TAPS="0.25 0.5 1.0"; SWEEP=0.5; TG=0.5; WIN=(--window 0.016) ;;
  reduced) # 201 drops in 2 s, 0.6 s to settle, dt 5e-6 s, a 1.5 cm stamp (a tenth of the pile)
    HALF=0.0075; PILE=(source[0].to=2.0 run.end_time=2.6 dem.dt=5e-6 $(stamp $HALF)); T0=2.6; SNAP=0.2; TAPS="0.5"; SWEEP=0.3; TG=0.3; WIN=(--window 0.012) ;;
  *) echo "usage: $0 [full|medium|reduced]" >&2; exit 2 ;;
esac
add() { /usr/bin/python3 -c "print(round($1 + $2, 6))"; }
mkdir -p "$OUT"

timed() {  # name: runs "$G" "$@" after the name and prints the wall time
  local name=$1
  shift
  echo "== $name: $G $*"
  local t0=$SECONDS
  "$G" "$@"
  echo "   $((SECONDS - t0)) s wall"
}
resume() {  # name end_time [--set ...]: a copy of the saved pile continued with a changed scene
  local name=$1 end=$2
  shift 2
  rm -rf "${OUT:?}/$name"
  cp -r "$OUT/pile" "$OUT/$name"
  timed "$name" run "$SCENE" --resume "$OUT/$name" -q --set "${PILE[@]}" run.end_time="$end" \
    output.snapshot_interval=0.1 output.series_interval=0.01 "$@"
}

if [[ ${REUSE_PILE:-0} == 1 && -f $OUT/pile/checkpoint.bin ]]; then
  echo "== pile: reusing $OUT/pile (REUSE_PILE=1)"
else
  timed pile run "$SCENE" --out "$OUT/pile" --overwrite -q --set "${PILE[@]}" output.snapshot_interval=$SNAP
fi
"$G" analyze "$OUT/pile" -q

# 4.3.1 tapping: the three floor pieces tap together.
for T in $TAPS; do
  vib=()
  for w in 0 1 2; do
    vib+=("wall[$w].vib_type=\"tapping\"" "wall[$w].vib_frequency=20.0" "wall[$w].vib_width=1.0e-4"
          "wall[$w].vib_window=[$T0,$(add "$T0" "$T")]")
  done
  resume "tap_$T" "$(add "$T0" "$T + 0.2")" "${vib[@]}"
  "$G" analyze "$OUT/tap_$T" -q
done

# 4.3.2 the stamp, displacement-controlled at 1 mm/s, each branch from the saved pile.
resume stamp_down "$(add "$T0" "$SWEEP")" "wall[1].velocity=[0.0,-1.0e-3]"
resume stamp_up "$(add "$T0" "$SWEEP")" "wall[1].velocity=[0.0,1.0e-3]"
"$PYTHON" "$S/stamp_curve.py" "$OUT/stamp_down" "$OUT/stamp_up" --png "$OUT/stamp_curve.png"
for r in stamp_down stamp_up; do  # floor profiles before (T0) and after, for the plots
  "$G" analyze "$OUT/$r" pressure --at "$T0" -q
  "$G" analyze "$OUT/$r" pressure -q
done

# 4.3.3 elastic constants: g lowered adiabatically over TG s, then 0.1 s at rest.
TEND=$(add "$T0" "$TG")
resume elastic "$(add "$TEND" 0.1)" 'gravity.type="linear"' 'gravity.magnitude=[9.81,0.00245]' \
  "gravity.window=[$T0,$TEND]"
# Test areas: ~150 grains at full size (the thesis); smaller piles need smaller areas to have
# interior ones (the strains are central differences): 4 x 4 grains (medium), 3 x 3 (reduced).
"$G" analyze "$OUT/elastic" strain stress --at "$T0" --reference "$(add "$TEND" 0.1)" "${WIN[@]}" -q

for r in pile $(for T in $TAPS; do echo "tap_$T"; done) elastic; do
  snap=$(ls -d "$OUT/$r"/analysis/snapshot_* | tail -1)
  "$PYTHON" scripts/plot_analysis.py "$snap" >/dev/null || echo "plot_analysis failed for $snap"
done

echo
echo "== measured ($S/summarize.py explains each figure)"
"$PYTHON" "$S/summarize.py" "$OUT" "$T0" "$HALF"
cat <<'TXT'

== thesis (gc2d spec 8.7)
tapping 20 Hz, 0.1 mm : the pile gets lower with the tapping time, the density homogenises, the
                        dip shrinks or vanishes
stamp (point source)  : withdrawn to p = -0.7 the load goes through an arch to a narrow zone next
                        to the stamp, distant floor unaffected; p(u) about point-symmetric about
                        (0, -0.1)
elastic (g -> 2.45e-3): nu_avg = 0.446 +- 0.137, E = 1.48e5 +- 1.08e5 N/m (two orders below the
                        grains' 1e7 N/m), u_zz > u_xx
TXT
