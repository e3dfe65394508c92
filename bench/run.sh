#!/usr/bin/env bash
# Builds the benchmarks in Release (build-bench/) and runs them, printing their figures.
#   bench/run.sh            full runs (a few minutes: the 4000x4000 textbook Dijkstra alone takes seconds)
#   bench/run.sh --quick    short runs, for a smoke test
# Environment: BUILD_DIR (default <repo>/build-bench), BENCH_DOMAIN (default 160; the lockstep
# bench uses the next few ids too, up to 169; paced_sim_bench uses BENCH_DOMAIN + 10, i.e. 170;
# experiment_bench.sh uses BENCH_DOMAIN + 20 to + 23, the runner's four jobs; executive_replan_bench
# BENCH_DOMAIN + 24 (lockstep) and + 46 (--paced: 206 by default), office_day_bench.sh BENCH_DOMAIN + 25),
# CYCLONEDDS_URI (default: the loopback profile),
# LOCKSTEP_DDS_EXTRA (a Cyclone config snippet to compare against the default, optional).
# The figures are noisy on a shared 2-core machine: read the ratios measured in the same run.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$repo/build-bench}"
domain="${BENCH_DOMAIN:-160}"
export CYCLONEDDS_URI="${CYCLONEDDS_URI:-file://$repo/deploy/dds/loopback.xml}"

quick=()
if [[ "${1:-}" == "--quick" ]]; then quick=(--quick); fi
# bench/run.sh --secure [--quick]: DDS Security against plain, both measured in the same run: the
# typed layer's round trips and throughput, lockstep ticks/s (docs/security.md).
if [[ "${1:-}" == "--secure" ]]; then
  if [[ "${2:-}" == "--quick" ]]; then quick=(--quick); fi
  cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  ninja -C "$build" dds_layer_bench lockstep_bench simulator behavior
  keys=$(mktemp -d)
  trap 'rm -rf "$keys"' EXIT
  bash "$repo/deploy/security/security.sh" set "$keys" "$repo/deploy/sets/demo-lockstep.set" >/dev/null
  bash "$repo/deploy/security/security.sh" add "$keys" bench operator --also 'bench/*' >/dev/null
  echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores, CYCLONEDDS_URI=$CYCLONEDDS_URI"
  CYCLONEDDS_URI="$CYCLONEDDS_URI,$(bash "$repo/deploy/security/security.sh" uri "$keys" bench --domain "$((domain + 2))")" \
    "$build/bin/dds_layer_bench" --domain "$domain" --secure-domain "$((domain + 2))" "${quick[@]}"
  "$build/bin/lockstep_bench" --domain "$((domain + 3))" --secure "$keys" "${quick[@]}"
  exit 0
fi

cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
ninja -C "$build" dds_layer_bench lockstep_bench field_bench radio_bench world_bench paced_sim_bench simulator behavior experiment_runner experiment_trial_host \
  courier_bench courier_fleet_bench planner_bench path_bench executive_bench \
  executive_replan_bench planner executive office_day_experiment courier courier_plot

echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores, CYCLONEDDS_URI=$CYCLONEDDS_URI"
"$build/bin/dds_layer_bench" --domain "$domain" "${quick[@]}"
extra=()
if [[ -n "${LOCKSTEP_DDS_EXTRA:-}" ]]; then extra=(--dds-extra "$LOCKSTEP_DDS_EXTRA"); fi
"$build/bin/lockstep_bench" --domain "$((domain + 1))" "${quick[@]}" "${extra[@]}"
"$build/bin/field_bench" "${quick[@]}"
"$build/bin/radio_bench" "${quick[@]}"
if [[ ${#quick[@]} -gt 0 ]]; then "$build/bin/world_bench" --ticks 30; else "$build/bin/world_bench"; fi
"$build/bin/paced_sim_bench" --domain "$((domain + 10))" "${quick[@]}"
"$repo/bench/experiment_bench.sh" "$build/bin" "$((domain + 20))" "${quick[@]}"
"$repo/bench/office_day_bench.sh" "$build/bin" "$((domain + 25))" "${quick[@]}"
"$build/bin/courier_bench" "${quick[@]}"
if [[ ${#quick[@]} -gt 0 ]]; then "$build/bin/courier_fleet_bench" --instances 2 --budget-ms 500; else "$build/bin/courier_fleet_bench"; fi
# planner_bench times MiniZinc + Gecode beside the planner when bench/install-minizinc.sh ran.
if [[ ${#quick[@]} -gt 0 ]]; then planner_quick=(--jobshop-seconds 5 --repeats 1); else planner_quick=(); fi
"$build/bin/planner_bench" --examples-dir "$repo/services/planner/examples" \
  --minizinc-model "$repo/bench/jobshop.mzn" "${planner_quick[@]}"
"$build/bin/executive_bench" "${quick[@]}"
"$build/bin/executive_replan_bench" --domain "$((domain + 24))" "${quick[@]}"
# Issue 28: fault -> new plan executing in paced time at ~1,000 tokens, beside ~85 tokens.
"$build/bin/executive_replan_bench" --paced --domain "$((domain + 46))" "${quick[@]}"
if [[ ${#quick[@]} -gt 0 ]]; then pairs=(--pairs 5); else pairs=(); fi
# path_bench writes OMPL benchmark logs and a summary: into the build folder, not over docs/.
"$build/bin/path_bench" "${pairs[@]}" --out "$build"
