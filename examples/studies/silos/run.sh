#!/bin/bash
# The silo studies of gc2d spec 8.3: runs the scenes of this folder one after the other, then
# `granulab analyze ... janssen packing` on the last snapshot, the plot script (if python3 has
# numpy and matplotlib), and prints the measured k, mu_j, rho_rel and the position of the
# pressure maximum against the thesis.
#   examples/studies/silos/run.sh                       # the four full-size silos (hours, see README.md)
#   examples/studies/silos/run.sh reduced slanted       # some of: reduced straight stepped slanted parabolic
#   SKIP_RUN=1 examples/studies/silos/run.sh straight   # analyse an existing run only
# Environment: GRANULAB (binary, default build/granulab), OUT (folder, default out/silos).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
bin=${GRANULAB:-$root/build/granulab}
out=${OUT:-$root/out/silos}
mkdir -p "$out"
[ $# -gt 0 ] || set -- straight stepped slanted parabolic

# Highest grain top [m] of a run's final state (y + circumradius), the free surface of the analysis.
surface() { awk -F, 'NR > 1 { t = $4 + $9; if (NR == 2 || t > m) m = t } END { printf "%.6f", m }' "$1/final.csv"; }

# The fit's notes of janssen.csv and the depth of the sigma_zz maximum: measured (5-row running
# mean, the rows are one test-area step apart) and theory (at the bottom row: no interior maximum).
report() {
    local dir=$1 name=$2 expect=$3
    local table
    table=$(ls -d "$dir"/analysis/snapshot_* | tail -1)/janssen.csv
    awk -F, -v name="$name" -v expect="$expect" '
        /^#/ { if ($0 ~ /# k = /) k = $0; if ($0 ~ /# mu_j = /) mu = $0; if ($0 ~ /# rho_rel = /) rho = $0; next }
        !hdr { hdr = 1; next }
        { n++; z[n] = $1; s[n] = $3; if ($5 > tmax) { tmax = $5; zt = $1 } }
        END {
            for (i = 3; i <= n - 2; i++) {
                m = (s[i - 2] + s[i - 1] + s[i] + s[i + 1] + s[i + 2]) / 5
                if (m > smax) { smax = m; zs = z[i] }
            }
            gsub(/# /, "", k); gsub(/# /, "", mu); gsub(/# /, "", rho)
            printf "%-10s measured: %s, %s, %s; sigma_zz max at z = %.3f m of %.3f m (fitted theory: %.3f m)\n", name, k, mu, rho, zs, z[n], zt
            printf "%-10s thesis:   %s\n", "", expect
        }' "$table"
}

for silo in "$@"; do
    case $silo in
    reduced) scene=straight_reduced; expect="k = 0.64 +- 0.19, mu_j = 0.33, rho_rel = 0.78 +- 0.03 (full size)" ;;
    straight) scene=straight; expect="k = 0.64 +- 0.19, mu_j = 0.33, rho_rel = 0.78 +- 0.03" ;;
    stepped) scene=stepped; expect="k = 0.64 +- 0.19, mu_j = 0.33; sigma_xx(h0) = 3.40 kN/m above the step" ;;
    slanted) scene=slanted; expect="k = 0.77 +- 0.24, mu_j = 0.30; sigma_zz max at z ~ 0.29 m" ;;
    parabolic) scene=parabolic; expect="k = 0.86 +- 0.14, mu_j = 0.30; sigma_zz max at z ~ 0.31 m" ;;
    *) echo "unknown silo '$silo' (reduced, straight, stepped, slanted, parabolic)" >&2; exit 2 ;;
    esac
    dir=$out/$silo
    if [ -z "${SKIP_RUN:-}" ]; then
        start=$(date +%s)
        "$bin" run "$here/$scene.toml" --out "$dir" --overwrite -q
        echo "$silo: run took $(($(date +%s) - start)) s"
    fi
    ys=$(surface "$dir")
    # The design surface of the stepped, slanted and parabolic silos is y = 0: shift the shape to
    # the measured surface y_s (z = y_s - y).
    case $silo in
    reduced) shape=straight:0.01; grid="--window 0.02:0.015 --step 0.02:0.0075" ;;
    straight) shape=straight:0.045; grid="--window 0.03:0.015 --step 0.015:0.0075" ;;
    stepped) shape=stepped:0.04,0.02,$(awk -v y="$ys" 'BEGIN { printf "%.5f", 0.25 + y }')
        grid="--window 0.02:0.015 --step 0.01:0.0075" ;;
    slanted) shape=slanted:-0.1087,$(awk -v y="$ys" 'BEGIN { printf "%.5f", 0.065 + 0.1087 * y }')
        grid="--window 0.035:0.03 --step 0.0175:0.01" ;;
    parabolic) shape=parabolic:100,$(awk -v y="$ys" 'BEGIN { printf "%.5f", 0.46 + y }')
        grid="--window 0.035:0.03 --step 0.0175:0.01" ;;
    esac
    # shellcheck disable=SC2086
    "$bin" analyze "$dir" janssen packing --silo "$shape" --surface "$ys" $grid
    snap=$(ls -d "$dir"/analysis/snapshot_* | tail -1)
    if python3 -c 'import numpy, matplotlib' 2>/dev/null; then
        python3 "$root/scripts/plot_analysis.py" "$snap" || echo "plot failed (see above)"
    else
        echo "(python3 numpy/matplotlib missing: no plots)"
    fi
    report "$dir" "$silo" "$expect" | tee -a "$out/results.txt"
done
