#!/usr/bin/env bash
# The day-in-office experiment's speed goals: a simulated 8-hour day with one courier in under
# 60 s of wall time, and the whole default experiment (5 strategies x 20 days) in under 10 min.
# Baseline measured in the same run: the same seeded day with every tick published
# (office_day --every-tick), so the figure shows what quiet ticks (idl/clock.idl) buy.
#   bench/office_day_bench.sh BIN_DIR DOMAIN [--quick]    (--quick: a 1-hour day)
# Outputs go to a temporary folder.
set -euo pipefail

bin="$1"
domain="$2"
hours=8
if [[ "${3:-}" == "--quick" ]]; then hours=1; fi
out="$(mktemp -d /tmp/office-day-bench.XXXXXX)"
trap 'rm -rf "$out"' EXIT

day() {  # day NAME [extra args]: one day of strategy (c); prints its CSV row's wall_s and on_time
  local name="$1"; shift
  "$bin/office_day" --days 1 --strategies c --hours "$hours" --parallel 1 --domain-base "$domain" \
    --seed 7 --out "$out/$name" "$@" > "$out/$name.log"
  awk -F, 'NR == 2 { print $17, $6, $4 }' "$out/$name/days.csv"
}

read -r every_s every_on_time jobs <<< "$(day every-tick --every-tick)"
read -r quiet_s quiet_on_time _ <<< "$(day quiet)"
quiet_ticks="$(sed -n 's/.* \([0-9]*\) ticks quiet.*/\1/p' "$out/quiet/logs/c-1-simulator.out" | tail -n 1)"
awk -v e="$every_s" -v q="$quiet_s" -v h="$hours" -v n="$jobs" -v eo="$every_on_time" -v qo="$quiet_on_time" \
    -v qt="$quiet_ticks" 'BEGIN {
  ticks = h * 7200
  printf "office_day_bench: one %d-hour day of strategy (c), %d jobs\n", h, n
  printf "  every tick published (baseline): %6.1f s wall, %d on time\n", e, eo
  printf "  quiet ticks:                     %6.1f s wall, %d on time, %d of %d ticks quiet (%.0f %%)\n", \
    q, qo, qt, ticks, 100 * qt / ticks
  printf "  speed-up %.1fx; goal for an 8-hour day: < 60 s\n", e / q
}'
