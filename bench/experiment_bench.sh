#!/usr/bin/env bash
# The robot-teams experiment's speed goal: all 6 x 30 trials of Table 1 in under 2 minutes on
# this machine, through the real processes. Baseline measured in the same run: a few trials one
# at a time, so the figure also shows what running trials side by side buys.
#   bench/experiment_bench.sh BIN_DIR DOMAIN [--quick]
# Prints the runner's progress, then the figures. Outputs go to a temporary folder.
set -euo pipefail

bin="$1"
domain="$2"
trials=30
baseline_trials=2
if [[ "${3:-}" == "--quick" ]]; then trials=3; baseline_trials=1; fi
out="$(mktemp -d /tmp/experiment-bench.XXXXXX)"
trap 'rm -rf "$out"' EXIT

seconds_of() {  # the runner's last line: "wrote ...: N trials in S s, F failed"
  sed -n 's/.* trials in \([0-9.]*\) s, .*/\1/p' "$1" | tail -n 1
}

"$bin/experiment_runner" --trials "$baseline_trials" --jobs 1 --domain "$domain" --out "$out/baseline" \
  > "$out/baseline.log"
baseline_s="$(seconds_of "$out/baseline.log")"
baseline_n=$((6 * baseline_trials))

"$bin/experiment_runner" --trials "$trials" --domain "$domain" --out "$out/full" | tee "$out/full.log"
full_s="$(seconds_of "$out/full.log")"
full_n=$((6 * trials))

awk -v bs="$baseline_s" -v bn="$baseline_n" -v fs="$full_s" -v fn="$full_n" 'BEGIN {
  per = bs / bn
  printf "experiment: %d trials in %.1f s (%.2f s per trial); goal for 180 trials: 120 s\n", fn, fs, fs / fn
  printf "  projected for 180 trials: %.1f s, ratio to the goal %.2f\n", fs / fn * 180, fs / fn * 180 / 120
  printf "  baseline, one trial at a time: %.2f s per trial (%d trials); side by side is %.2fx faster\n",
         per, bn, per / (fs / fn)
}'
