#!/usr/bin/env bash
# The main demo: installs, builds the demo's programs, starts the simulator (built-in demo world,
# real time) and the controller of robot r1 as separate DDS processes, sends r1 a goal on the far
# side of a wall and shows its progress until it arrives. Then the world keeps running, to be
# explored from another terminal, until Ctrl-C stops everything. Leaves a picture of the run
# (run.svg) in the run folder.
#
# Options: --domain N (default $AUTONOMY_DOMAIN or 0), --no-setup (skip install and build),
#          --goal X Y (default 18 2),
#          --exit-when-reached (for scripts: stop everything and end once the goal is reached;
#          exit code 0 when reached, 1 otherwise), --secure (DDS Security: docs/security.md),
#          --viewer-port P (the live view in a browser, default 8080: docs/viewer.md), --no-viewer.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

domain=${AUTONOMY_DOMAIN:-0}
setup=1
goal_x=18
goal_y=2
exit_when_reached=0
secure=()  # --secure: launch.sh --profile secure
viewer_port=8080  # the viewer's page (docs/viewer.md); "" = no viewer
while [ $# -gt 0 ]; do
  case $1 in
    --domain) domain=$2; shift 2 ;;
    --no-setup) setup=0; shift ;;
    --goal) goal_x=$2; goal_y=$3; shift 3 ;;
    --exit-when-reached) exit_when_reached=1; shift ;;
    --secure) secure=(--profile secure); shift ;;
    --viewer-port) viewer_port=$2; shift 2 ;;
    --no-viewer) viewer_port=""; shift ;;
    -h|--help) sed -n '2,12p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "demo: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done

if [ $setup -eq 1 ]; then
  bash "$repo/deploy/install-deps.sh"
  echo "demo: building the simulator, the behavior controller and the autonomy CLI (first time: a few minutes)"
  bash "$repo/deploy/build.sh" --demo
fi

cli="$repo/build/bin/autonomy"
export CYCLONEDDS_URI="file://$repo/deploy/dds/loopback.xml"
export AUTONOMY_DOMAIN=$domain
run_dir="$repo/runs/demo-$(date +%Y%m%d-%H%M%S)"

# The demo set, plus the viewer (not secured: it has no identity in deploy/security/access.table yet).
[ ${#secure[@]} -eq 0 ] || viewer_port=""
set_file=$(bash "$repo/deploy/viewer.sh" set demo "$run_dir" "$viewer_port")
bash "$repo/deploy/launch.sh" --detach "${secure[@]}" --domain "$domain" --run-dir "$run_dir" "$set_file"
viewer_says=$(bash "$repo/deploy/viewer.sh" address "$run_dir" "$viewer_port" 2>&1)
[ -z "$viewer_says" ] || echo "demo: $viewer_says"
# Secured, this script's own tools (and the commands it prints) act as the operator.
[ ${#secure[@]} -eq 0 ] || CYCLONEDDS_URI+=",$(bash "$repo/deploy/security/security.sh" uri "${AUTONOMY_SECURITY_DIR:-$repo/runs/security}" operator)"
finish() {
  bash "$repo/deploy/launch.sh" stop "$run_dir" || true
  echo "demo: picture of the run: $run_dir/run.svg; trajectory: $run_dir/trajectory.csv; logs: $run_dir"
}
trap finish EXIT
trap 'exit 130' INT TERM
launcher_alive() { local pid; pid=$(cat "$run_dir/launch.pid" 2>/dev/null) && kill -0 "$pid" 2>/dev/null && echo "$pid"; }

cat <<MSG

demo: the simulator and r1's controller are running on DDS domain $domain. From another terminal:
  export CYCLONEDDS_URI=$CYCLONEDDS_URI AUTONOMY_DOMAIN=$domain
  $cli topic echo autonomy/robot/state      # r1's state as JSON lines
  $cli node list                            # the processes, from their heartbeats
  $cli topic list                           # every topic on the domain

MSG
"$cli" node list

echo "demo: sending r1 the goal ($goal_x, $goal_y), beyond the wall"
"$cli" topic pub autonomy/nav/goal "{\"robot_id\":\"r1\",\"goal_id\":\"demo-1\",\"x\":$goal_x,\"y\":$goal_y}"

started=$SECONDS
result=""
while [ $((SECONDS - started)) -lt 120 ]; do
  status=$("$cli" topic echo autonomy/nav/goal_status --count 1 --timeout 2 2>/dev/null || true)
  pose=$("$cli" topic echo autonomy/robot/state --count 1 --timeout 2 2>/dev/null || true)
  state=$(jq -r 'select(.goal_id == "demo-1") | .state' <<<"$status" 2>/dev/null || true)
  if [ -n "$pose" ]; then
    printf 'demo: %3ds  r1 at (%6.2f, %6.2f)  goal %s\n' $((SECONDS - started)) \
      "$(jq -r .x <<<"$pose")" "$(jq -r .y <<<"$pose")" "${state:-pending}"
  fi
  case $state in
    reached) result=reached; break ;;
    failed|rejected|preempted) result="$state: $(jq -r .reason <<<"$status")"; break ;;
  esac
  sleep 1
done

echo
if [ "$result" != reached ]; then
  echo "demo: r1 did not reach its goal: ${result:-no answer within 120 s}; logs in $run_dir" >&2
  exit 1
fi
echo "demo: r1 reached its goal ($goal_x, $goal_y) in $((SECONDS - started)) s"
if [ $exit_when_reached -eq 0 ]; then
  cat <<MSG

demo: the world keeps running for you to explore. From another terminal:
  export CYCLONEDDS_URI=$CYCLONEDDS_URI AUTONOMY_DOMAIN=$domain
  $cli topic echo autonomy/robot/state      # r1's state as JSON lines
  $cli topic pub autonomy/nav/goal '{"robot_id":"r1","goal_id":"back","x":2,"y":2}'   # send r1 back
  $cli node list                            # the processes, from their heartbeats
demo: Ctrl-C here stops everything.
MSG
  trap 'stop_requested=1' INT TERM
  stop_requested=0
  # Until Ctrl-C, or until the set stops by itself (its launcher reports why in launch.log).
  while [ $stop_requested -eq 0 ] && [ -n "$(launcher_alive)" ]; do
    sleep 1 &
    wait $! || true
  done
  if [ $stop_requested -eq 0 ]; then
    echo "demo: the set stopped by itself; the launcher's report:" >&2
    tail -n 20 "$run_dir/launch.log" >&2
    exit 1
  fi
  echo
fi
