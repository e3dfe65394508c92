#!/usr/bin/env bash
# The robot-teams experiment's speed goal (issue 28): all 6 x 30 trials of Table 1 in under 30 s on
# this machine, with the results of the process-per-node runs. Measured in the same run:
#   1. the 180 trials as the runner runs them by default (a trial's nodes in one process);
#   2. the baseline: the 30 "reactive" trials with a process per node (--processes separate, as
#      before issue 28), and the same 30 trials the default way: their ratio, and the 180-trial
#      figure projected for the baseline. The runner draws every configuration's seeds whatever
#      --only selects, so these are the very trials of run 1: their CSV rows must be identical.
#   bench/experiment_bench.sh BIN_DIR DOMAIN [--quick]
# Uses DOMAIN to DOMAIN + JOBS - 1 (environment JOBS, default 4: the runner's trials at a time).
# Prints the runner's progress, then the figures (wall seconds; CPU seconds of the runner and its
# children). Outputs go to a temporary folder.
set -euo pipefail

bin="$1"
domain="$2"
trials=30
if [[ "${3:-}" == "--quick" ]]; then trials=3; fi
goal_s=30
jobs="${JOBS:-4}"
out="$(mktemp -d /tmp/experiment-bench.XXXXXX)"
trap 'rm -rf "$out"' EXIT

# run NAME SHOW ARGS...: the runner with ARGS, its output in NAME.log (and on the console if SHOW is
# "show"), "wall cpu" seconds (CPU of the runner and the trials it ran) in NAME.time.
run() {
  local name="$1" show="$2"
  shift 2
  /usr/bin/time -f "%e %U %S" -o "$out/$name.rusage" "$bin/experiment_runner" --trials "$trials" --jobs "$jobs" \
    --domain "$domain" --out "$out/$name" "$@" | if [[ "$show" == show ]]; then tee "$out/$name.log"; else cat > "$out/$name.log"; fi
  awk '{ printf "%s %.2f\n", $1, $2 + $3 }' "$out/$name.rusage" > "$out/$name.time"
}
rows_of() {  # the CSV rows of one configuration
  grep "^$2," "$out/$1/trials.csv"
}

run full show
full_n="$((6 * trials))"
run baseline quiet --only reactive --processes separate
run one quiet --only reactive --processes one
if [[ "$(rows_of full reactive)" == "$(rows_of baseline reactive)" && "$(rows_of one reactive)" == "$(rows_of baseline reactive)" ]]; then
  same="identical"
else
  same="DIFFERENT"
fi

read -r full_s full_cpu < "$out/full.time"
read -r base_wall base_cpu < "$out/baseline.time"
read -r one_wall one_cpu < "$out/one.time"
awk -v fs="$full_s" -v fc="$full_cpu" -v fn="$full_n" -v goal="$goal_s" -v bw="$base_wall" -v bc="$base_cpu" -v ow="$one_wall" \
    -v oc="$one_cpu" -v n="$trials" -v jobs="$jobs" -v same="$same" 'BEGIN {
  printf "experiment: %d trials in %.1f s (%.2f s per trial, %.1f CPU-s), one process per trial, %d at a time; goal for 180 trials: %d s\n",
         fn, fs, fs / fn, fc, jobs, goal
  printf "  180 trials: %.1f s, ratio to the goal %.2f\n", fs / fn * 180, fs / fn * 180 / goal
  printf "  baseline, a process per node (before issue 28), the same %d reactive trials: %.1f s wall, %.1f CPU-s;\n",
         n, bw, bc
  printf "    one process per trial: %.1f s wall, %.1f CPU-s: %.2fx less wall time, %.2fx less CPU\n", ow, oc, bw / ow, bc / oc
  printf "    baseline projected for 180 trials: %.1f s; results of the two ways: %s\n", fs / fn * 180 * bw / ow, same
}'
[[ "$same" == identical ]]  # a difference fails the bench (and bench/run.sh)
