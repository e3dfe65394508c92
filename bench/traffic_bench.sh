#!/usr/bin/env bash
# Fleet traffic (docs/traffic.md) against no traffic, side by side in one run, in lockstep on the
# office floor (deploy/scenarios/office.pbtxt, one behavior per robot):
#   doorway  four robots cross doorway A-114 from both sides (tests/integration/traffic_test.cpp's
#            case): two in A-114 leave for the classroom, two in the hallway come in;
#   hall     two robots meet head-on in the 1.8 m hallway (with traffic one gives way).
# Per case and mode: goals reached / blocked (with the reasons), the closest two robots came
# (centre distance, from the simulator's trajectory: 0.60 m is contact for 0.3 m robots) and the
# sim time the last goal ended (the simulator stops once every goal is reached, else at 150 s).
#   bash bench/traffic_bench.sh            (build/bin: simulator, behavior)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=$repo/build/bin
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export CYCLONEDDS_URI=file://$repo/deploy/dds/loopback.xml
domain=${TRAFFIC_BENCH_DOMAIN:-142}

# run CASE MODE ROBOT:SX:SY:STHETA:GX:GY ...
run() {
  local case=$1 mode=$2; shift 2
  local dir=$work/$case-$mode wait=() pids=()
  mkdir -p "$dir"
  for spec in "$@"; do wait+=("behavior/${spec%%:*}"); done
  "$bin/simulator" --domain "$domain" --world-check 0 --config "$repo/deploy/scenarios/office.pbtxt" --without-robots \
    --stop-when-finished --max-ticks 1500 --wait-for "${wait[@]}" --trajectory "$dir/traj.csv" --log-dir "$dir" \
    >"$dir/sim.out" 2>&1 &
  local sim=$!
  for spec in "$@"; do
    IFS=: read -r id sx sy st gx gy <<<"$spec"
    "$bin/behavior" --domain "$domain" --robot "$id" --start "$sx" "$sy" "$st" --goal "$gx" "$gy" "--$mode" \
      --log-dir "$dir" >"$dir/$id.out" 2>&1 &
    pids+=($!)
  done
  wait "$sim" || true
  kill "${pids[@]}" 2>/dev/null || true
  wait "${pids[@]}" 2>/dev/null || true
  python3 - "$dir" "$case" "$mode" <<'PY'
import csv, collections, glob, math, os, re, sys
d, case, mode = sys.argv[1:4]
ticks = collections.defaultdict(dict)
last_t = 0.0
for r in csv.DictReader(open(os.path.join(d, "traj.csv"))):
    ticks[int(r["tick"])][r["robot"]] = (float(r["x"]), float(r["y"]))
    last_t = max(last_t, float(r["time_s"]))
closest = min((math.dist(v[a], v[b]) for v in ticks.values() for a in v for b in v if a < b), default=float("nan"))
reached, blocked = 0, []
for f in sorted(glob.glob(os.path.join(d, "r*.out"))):
    text = open(f).read()
    if re.search(r"goal cli-goal reached", text): reached += 1
    m = re.findall(r"goal cli-goal blocked: (.*)", text)
    if m: blocked.append(os.path.basename(f)[:-4] + ": " + m[-1])
n = len(glob.glob(os.path.join(d, "r*.out")))
print(f"{case:8s} {mode:10s} reached {reached}/{n}  closest {closest:.2f} m  last tick at {last_t:6.1f} s")
for b in blocked: print(f"{'':20s}blocked {b}")
PY
  domain=$((domain + 1))
}

doorway=("r1:16.8:4.0:1.57:14.5:12.0" "r2:18.4:4.0:1.57:13.0:12.5" "r3:21.0:8.0:3.14:17.0:3.0" "r4:23.0:8.0:3.14:18.5:2.5")
hall=("r1:10.0:8.0:0:26.0:8.0" "r2:26.0:8.0:3.14:10.0:8.0")
for mode in traffic no-traffic; do run doorway "$mode" "${doorway[@]}"; done
for mode in traffic no-traffic; do run hall "$mode" "${hall[@]}"; done
