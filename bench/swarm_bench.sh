#!/usr/bin/env bash
# Fleet traffic, a swarm (docs/traffic.md, issue 25): 1, 2, 4, 6 and 10 robots on the office floor
# (deploy/scenarios/office.pbtxt, one behavior each, lockstep), each sent seeded random goals one
# after another, with traffic and with `behavior --no-traffic` (the baseline) in the same run.
# Per size and mode one line: goals reached per simulated hour, goals that ended otherwise (and
# why), the longest goal, the closest two robots came and the robot-ticks in contact (the
# simulator's trajectory: its ground truth).
#
# It runs tests/integration/traffic_swarm_test.cpp's test with its environment knobs.
#   bash bench/swarm_bench.sh [--sim-s 1800] [--sizes "1 2 4 6 10"] [--seed 25] [--modes "traffic no-traffic"]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
test_bin=${SWARM_TEST_BIN:-$repo/build/bin/traffic_swarm_integration_test}
[[ -x $test_bin ]] || test_bin=$repo/build/tests/traffic_swarm_integration_test
[[ -x $test_bin ]] || { echo "swarm_bench: no traffic_swarm_integration_test binary (build it first)" >&2; exit 2; }
sim_s=1800 sizes="1 2 4 6 10" seed=25 modes="traffic no-traffic"
while (($#)); do
  case $1 in
    --sim-s) sim_s=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --modes) modes=$2; shift 2 ;;
    *) echo "swarm_bench: unknown option $1 (--sim-s S, --sizes \"N ...\", --seed N, --modes \"traffic no-traffic\")" >&2; exit 2 ;;
  esac
done
domain=${SWARM_BENCH_DOMAIN:-106}
echo "swarm bench: office floor, lockstep, ${sim_s} s simulated per run, seed ${seed}; load average $(cut -d' ' -f1-3 /proc/loadavg)"
for n in $sizes; do
  for mode in $modes; do
    start=$(date +%s)
    out=$(SWARM_ROBOTS=$n SWARM_SIM_S=$sim_s SWARM_SEED=$seed SWARM_DOMAIN=$domain SWARM_WALL_S=$((sim_s + 300)) \
          SWARM_TRAFFIC=$([[ $mode == traffic ]] && echo 1 || echo 0) \
          "$test_bin" --gtest_filter='TrafficSwarmTest.*' 2>&1) || true
    grep '^swarm:' <<<"$out" || { echo "robots $n mode $mode: no figures; the test said:"; tail -20 <<<"$out"; }
    grep -E '^\s*(Expected|Value of|Which is|  Actual|.*Failure)' <<<"$out" | head -6 || true
    echo "swarm:   ($(( $(date +%s) - start )) s wall, load average $(cut -d' ' -f1-3 /proc/loadavg))"
  done
done
