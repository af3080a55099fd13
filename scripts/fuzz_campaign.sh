#!/usr/bin/env bash
# Fuzz campaign of the scene readers (issue 11 acceptance): runs build/granulab_fuzz (Release) for
# MINUTES of wall time (default 15). The harness dies on a crash or a hang (the input saved); the
# campaign then goes on with the next seed until the time is spent. Prints the mutants, the
# outcomes per class, crashes, hangs over the per-input limit and the exit-status classes.
# Usage: scripts/fuzz_campaign.sh [MINUTES]
# Environment: BUILD_DIR (default build), FINDINGS (default BUILD_DIR/fuzz-campaign), SEED (first
# seed, default 1), HANG_SECONDS (per-input limit, default 20).
set -euo pipefail
cd "$(dirname "$0")/.."
minutes="${1:-15}"
build="${BUILD_DIR:-build}"
findings="${FINDINGS:-$build/fuzz-campaign}"
seed="${SEED:-1}"
hang="${HANG_SECONDS:-20}"
cmake --build "$build" --target granulab_fuzz -- --quiet
mkdir -p "$findings"
log="$findings/campaign.log"
: >"$log"

declare -A total=([mutants]=0 [ok]=0 [bad_input]=0 [unstable]=0 [exceptions]=0 [crashes]=0 [hangs]=0)
declare -A rcs=()
runs=0
start=$(date +%s)
end=$((start + minutes * 60))
while [ "$(date +%s)" -lt "$end" ]; do
  left=$((end - $(date +%s)))
  rc=0
  out=$("$build/granulab_fuzz" --seconds "$left" --seed "$seed" --findings "$findings" \
        --hang-seconds "$hang" 2>>"$log") || rc=$?
  runs=$((runs + 1))
  rcs[$rc]=$((${rcs[$rc]:-0} + 1))
  line=$(grep '^fuzz-summary' <<<"$out" | tail -1 || true)
  if [ -z "$line" ]; then
    echo "fuzz_campaign: seed $seed ended with status $rc and no summary (see $log)" >&2
  fi
  for kv in ${line#fuzz-summary }; do
    key=${kv%%=*}
    total[$key]=$((${total[$key]:-0} + ${kv#*=}))
  done
  seed=$((seed + 1))
done

findings_total=$((total[exceptions] + total[crashes] + total[hangs]))
echo "fuzz campaign: $minutes min, $runs harness run(s) (seeds ${SEED:-1}..$((seed - 1))), findings in $findings/"
echo "  mutants     ${total[mutants]}"
echo "  ok          ${total[ok]}       (granulab exit status 0)"
echo "  bad input   ${total[bad_input]}       (exit status 2)"
echo "  unstable    ${total[unstable]}       (exit status 3)"
echo "  exceptions  ${total[exceptions]}       (exit status 1: an exception other than bad input)"
echo "  crashes     ${total[crashes]}       (signal or sanitizer error)"
echo "  hangs       ${total[hangs]}       (an input over $hang s of CPU)"
echo -n "  harness exit statuses:"
for rc in "${!rcs[@]}"; do echo -n " $rc x${rcs[$rc]}"; done
echo "   (0 clean, 1 findings, 124 hang, >128 signal)"
grep -h '^fuzz: \(FINDING\|CRASH\|HANG\|SANITIZER\)' "$log" | sed 's/^/  /' || true
[ "$findings_total" -eq 0 ]
