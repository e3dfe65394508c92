#!/usr/bin/env bash
# The courier paper's example live: builds what it needs, starts the office floor in real time
# with RHINO's behavior and the courier scheduler (deploy/sets/courier.set), sends the paper's two
# commands of section 2 and follows the jobs until both ended. A-120 closes after the red letter
# is loaded and opens again while the green book is fetched (the paper's Fig. 5). Then the world
# keeps running for more commands from another terminal until Ctrl-C.
#
# Options: --domain N (default $AUTONOMY_DOMAIN or 0), --no-setup (skip install and build),
#          --exit-when-done (stop everything once both jobs ended; exit 0 when both completed),
#          --fleet (two couriers: deploy/sets/courier-fleet.set adds rhino2 at the hallway's east end),
#          --secure (DDS Security, every process on its identity: docs/security.md).
#          --path-planner grid|ompl (rhino's go-to paths: the grid field's controller, default, or
#          OMPL Reeds-Shepp paths followed by pure pursuit: deploy/sets/courier-ompl.set).
#          --viewer-port P (the live view in a browser, default 8080: docs/viewer.md), --no-viewer.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

domain=${AUTONOMY_DOMAIN:-0}
setup=1
exit_when_done=0
fleet=0
path_planner=grid
secure=()  # --secure: launch.sh --profile secure
viewer_port=8080  # the viewer's page (docs/viewer.md); "" = no viewer
while [ $# -gt 0 ]; do
  case $1 in
    --domain) domain=$2; shift 2 ;;
    --no-setup) setup=0; shift ;;
    --exit-when-done) exit_when_done=1; shift ;;
    --fleet) fleet=1; shift ;;
    --secure) secure=(--profile secure); shift ;;
    --viewer-port) viewer_port=$2; shift 2 ;;
    --no-viewer) viewer_port=""; shift ;;
    --path-planner)
      case ${2:-} in
        grid) path_planner=grid ;;
        ompl) path_planner=ompl ;;
        *) echo "courier-demo: --path-planner takes grid or ompl, not '${2:-}'" >&2; exit 2 ;;
      esac
      shift 2 ;;
    -h|--help) sed -n '2,14p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "courier-demo: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
case $fleet,$path_planner in
  0,grid) set_name=courier ;;
  0,ompl) set_name=courier-ompl ;;
  1,grid) set_name=courier-fleet ;;
  *) echo "courier-demo: --fleet runs on the grid controller only (no courier-fleet set with OMPL yet)" >&2; exit 2 ;;
esac

if [ $setup -eq 1 ]; then
  bash "$repo/deploy/install-deps.sh"
  echo "courier-demo: building the simulator, the behavior controller, the courier and the autonomy CLI"
  bash "$repo/deploy/build.sh" --target simulator --target behavior --target courier --target autonomy --target viewer
fi

cli="$repo/build/bin/autonomy"
export CYCLONEDDS_URI="file://$repo/deploy/dds/loopback.xml"
export AUTONOMY_DOMAIN=$domain
run_dir="$repo/runs/courier-$(date +%Y%m%d-%H%M%S)"

# Plus the viewer (not secured: it has no identity in deploy/security/access.table yet).
[ ${#secure[@]} -eq 0 ] || viewer_port=""
set_file=$(bash "$repo/deploy/viewer.sh" set "$set_name" "$run_dir" "$viewer_port")
bash "$repo/deploy/launch.sh" --detach "${secure[@]}" --domain "$domain" --run-dir "$run_dir" "$set_file"
viewer_says=$(bash "$repo/deploy/viewer.sh" address "$run_dir" "$viewer_port" 2>&1)
[ -z "$viewer_says" ] || echo "courier-demo: $viewer_says"
# Secured, this script's own tools (and the commands it prints) act as the operator.
[ ${#secure[@]} -eq 0 ] || CYCLONEDDS_URI+=",$(bash "$repo/deploy/security/security.sh" uri "${AUTONOMY_SECURITY_DIR:-$repo/runs/security}" operator)"
finish() {
  bash "$repo/deploy/launch.sh" stop "$run_dir" || true
  echo "courier-demo: picture: $run_dir/run.svg; events: $run_dir/events.jsonl; journal: $run_dir/courier.db; logs: $run_dir"
}
trap finish EXIT
trap 'exit 130' INT TERM

"$cli" courier send "put the red letter on the meeting table in room A-111 on the desk in room A-120 within 1 minute"
"$cli" courier send "deliver the green book from the librarian's desk in room A-110 to the desk in room A-114"
cat <<MSG

courier-demo: rhino is on its way. From another terminal:
  export CYCLONEDDS_URI=$CYCLONEDDS_URI AUTONOMY_DOMAIN=$domain
  $cli courier jobs                                  # every job's state
  $cli topic echo autonomy/courier/job_status        # job changes as JSON lines
  $cli topic echo autonomy/courier/schedule          # rhino's schedule and its door assumptions
  $cli topic echo autonomy/robot/door_observation    # what rhino sees of the doors

MSG
started=$SECONDS
ended=""
while [ $((SECONDS - started)) -lt 300 ]; do
  jobs=$("$cli" courier jobs --timeout 0.5 2>/dev/null || true)
  line=$(awk 'NR > 1 { printf "%s %s%s  ", $1, $2, ($3 != "" && $2 == "underway") ? "/" $3 : "" }' <<<"$jobs")
  printf 'courier-demo: %3ds  %s\n' $((SECONDS - started)) "$line"
  done_count=$(awk 'NR > 1 && ($2 == "completed" || $2 == "failed" || $2 == "cancelled")' <<<"$jobs" | wc -l)
  if [ "$done_count" -ge 2 ]; then ended=$jobs; break; fi
  sleep 2
done
echo
if [ -z "$ended" ]; then
  echo "courier-demo: the jobs did not end within 300 s; logs in $run_dir" >&2
  exit 1
fi
echo "$ended"
grep -v '"kind":"heading"' "$run_dir/events.jsonl" | jq -r '"  " + .time + "  " + .text' 2>/dev/null || true
if [ $exit_when_done -eq 1 ]; then
  [ "$(awk 'NR > 1 && $2 == "completed"' <<<"$ended" | wc -l)" -ge 2 ]
  exit $?
fi
echo "courier-demo: the office keeps running; send more with '$cli courier send \"...\"'. Ctrl-C stops everything."
trap 'exit 0' INT TERM
while :; do sleep 1 & wait $! || true; done
