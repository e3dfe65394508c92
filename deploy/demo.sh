#!/usr/bin/env bash
# The main demo: installs, builds, starts the simulator (built-in demo world, real time) and the
# controller of robot r1 as separate DDS processes, sends r1 a goal on the far side of a wall and
# shows its progress until it arrives. Leaves a picture of the run (run.svg) in the run folder.
#
# Options: --domain N (default $AUTONOMY_DOMAIN or 0), --no-setup (skip install and build),
#          --goal X Y (default 18 2).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

domain=${AUTONOMY_DOMAIN:-0}
setup=1
goal_x=18
goal_y=2
while [ $# -gt 0 ]; do
  case $1 in
    --domain) domain=$2; shift 2 ;;
    --no-setup) setup=0; shift ;;
    --goal) goal_x=$2; goal_y=$3; shift 3 ;;
    -h|--help) sed -n '2,8p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "demo: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done

if [ $setup -eq 1 ]; then
  bash "$repo/deploy/install-deps.sh"
  echo "demo: building (first time: a few minutes)"
  bash "$repo/deploy/build.sh"
fi

cli="$repo/build/bin/autonomy"
export CYCLONEDDS_URI="file://$repo/deploy/dds/loopback.xml"
export AUTONOMY_DOMAIN=$domain
run_dir="$repo/runs/demo-$(date +%Y%m%d-%H%M%S)"

bash "$repo/deploy/launch.sh" --detach --domain "$domain" --run-dir "$run_dir" demo
trap 'bash "$repo/deploy/launch.sh" stop "$run_dir"' EXIT
trap 'exit 130' INT TERM

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
if [ "$result" = reached ]; then
  echo "demo: r1 reached its goal ($goal_x, $goal_y) in $((SECONDS - started)) s"
else
  echo "demo: r1 did not reach its goal: ${result:-no answer within 120 s}; logs in $run_dir" >&2
fi
bash "$repo/deploy/launch.sh" stop "$run_dir"
trap - EXIT
echo "demo: picture of the run: $run_dir/run.svg; trajectory: $run_dir/trajectory.csv; logs: $run_dir"
[ "$result" = reached ]
