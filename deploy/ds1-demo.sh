#!/usr/bin/env bash
# The Remote Agent Experiment of May 1999 live: builds what it needs, writes the DS1-like
# scenario (deploy/scenarios/ds1.pbtxt) with the faults asked for into a run folder, starts the
# planner, the executive and the simulator in lockstep (deploy/sets/ds1.set), follows the
# executive's status until the day is flown, then prints the report (planned against executed
# timelines in plan.svg, faults and responses, goals) and stops everything.
#
# Options: --domain N (default $AUTONOMY_DOMAIN or 0), --no-setup (skip install and build),
#          --faults LIST (comma-separated ids of the scenario's commented faults: micas-stuck-on,
#          lpe-failed, power-sensor-false, thruster-x-stuck, ips-unconfirmed; "all" for the five;
#          default none),
#          --rover (the robot domain instead: a rover's survey on the field, deploy/sets/rover.set;
#          its drives become go-to goals of the behavior controller), --secure (DDS Security:
#          docs/security.md), --viewer-port P (the live view, default 8080: docs/viewer.md),
#          --no-viewer.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

domain=${AUTONOMY_DOMAIN:-0}
setup=1
faults=""
set_name=ds1
secure=()  # --secure: launch.sh --profile secure
viewer_port=8080  # the viewer's page (docs/viewer.md); "" = no viewer
while [ $# -gt 0 ]; do
  case $1 in
    --domain) domain=$2; shift 2 ;;
    --no-setup) setup=0; shift ;;
    --faults) faults=$2; shift 2 ;;
    --rover) set_name=rover; shift ;;
    --secure) secure=(--profile secure); shift ;;
    --viewer-port) viewer_port=$2; shift 2 ;;
    --no-viewer) viewer_port=""; shift ;;
    -h|--help) sed -n '2,15p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "ds1-demo: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
all="micas-stuck-on,lpe-failed,power-sensor-false,thruster-x-stuck,ips-unconfirmed"
[ "$faults" = all ] && faults=$all
if [ $set_name = rover ] && [ -n "$faults" ]; then
  echo "ds1-demo: --faults is for the spacecraft, not with --rover" >&2
  exit 2
fi

if [ $setup -eq 1 ]; then
  bash "$repo/deploy/install-deps.sh"
  echo "ds1-demo: building the simulator, the planner, the executive and the autonomy CLI"
  bash "$repo/deploy/build.sh" --target simulator --target planner --target executive --target autonomy \
    --target behavior --target viewer
fi

cli="$repo/build/bin/autonomy"
export CYCLONEDDS_URI="file://$repo/deploy/dds/loopback.xml"
export AUTONOMY_DOMAIN=$domain
run_dir="$repo/runs/$set_name-$(date +%Y%m%d-%H%M%S)"
mkdir -p "$run_dir"
[ $set_name = ds1 ] && cp "$repo/deploy/scenarios/ds1.pbtxt" "$run_dir/ds1.pbtxt"
IFS=, read -ra chosen <<<"$faults"
for id in "${chosen[@]}"; do
  [ -z "$id" ] && continue
  grep -q "# faults { id: \"$id\"" "$run_dir/ds1.pbtxt" ||
    { echo "ds1-demo: no fault '$id' in deploy/scenarios/ds1.pbtxt (known: $all)" >&2; exit 2; }
  sed -i "s|# faults { id: \"$id\"|faults { id: \"$id\"|" "$run_dir/ds1.pbtxt"
done
echo "ds1-demo: $set_name, faults: ${faults:-none}; run folder $run_dir"

# Plus the viewer (not secured: it has no identity in deploy/security/access.table yet).
[ ${#secure[@]} -eq 0 ] || viewer_port=""
set_file=$(bash "$repo/deploy/viewer.sh" set "$set_name" "$run_dir" "$viewer_port")
bash "$repo/deploy/launch.sh" --detach "${secure[@]}" --domain "$domain" --run-dir "$run_dir" "$set_file"
viewer_says=$(bash "$repo/deploy/viewer.sh" address "$run_dir" "$viewer_port" 2>&1)
[ -z "$viewer_says" ] || echo "ds1-demo: $viewer_says"
# Secured, this script's own tools (and the commands it prints) act as the operator.
[ ${#secure[@]} -eq 0 ] || CYCLONEDDS_URI+=",$(bash "$repo/deploy/security/security.sh" uri "${AUTONOMY_SECURITY_DIR:-$repo/runs/security}" operator)"
finish() { bash "$repo/deploy/launch.sh" stop "$run_dir" || true; }
trap finish EXIT
trap 'exit 130' INT TERM

started=$SECONDS
while [ ! -s "$run_dir/report.md" ]; do
  if [ $((SECONDS - started)) -gt 600 ]; then
    echo "ds1-demo: the mission was not finished within 600 s; logs in $run_dir" >&2
    exit 1
  fi
  # The set stopped (a process beyond its respawns, or stopped from outside): say so, with the
  # launcher's last words, instead of polling on in silence.
  case $(cat "$run_dir/launch.state" 2>/dev/null || true) in
    stopping|stopped)
      echo "ds1-demo: the set stopped before the mission ended; its launcher said:" >&2
      tail -n 15 "$run_dir/launch.log" >&2 || true
      exit 1 ;;
  esac
  status=$("$cli" topic echo autonomy/executive/status --count 1 --timeout 2 2>/dev/null || true)
  if [ -n "$status" ]; then
    jq -r '"ds1-demo: \(.state) tick \(.tick): \(.goals_achieved | length) goals achieved, \(.goals_lost | length) lost, \(.replans) replans, executing \(.executing | join("; "))"' <<<"$status" 2>/dev/null | cut -c1-200
  else
    echo "ds1-demo: no executive status for 2 s (restarting?); the launcher's log: $run_dir/launch.log"
  fi
  sleep 2
done
sleep 1
cat "$run_dir/report.md"
echo
echo "ds1-demo: report $run_dir/report.md, timelines $run_dir/plan.svg, logs $run_dir"
