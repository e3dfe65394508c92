#!/usr/bin/env bash
# The day-in-office experiment (issue 10) in one command: builds what it needs, then runs the
# courier strategies a..e over seeded simulated working days through the real simulator,
# behavior and courier processes over DDS in lockstep (build/bin/office_day), with a line of
# progress per day. Writes days.csv, report.md, on-time.svg, on-time-by-day.svg and the first
# day's trajectory and Gantt per strategy into the run folder.
#
# Options: --no-setup (skip install and build); everything else goes to office_day
#          (--days 20, --strategies a,b,c,d,e, --hours 8, --parallel 5, --out DIR, ...; see
#          build/bin/office_day --help).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
setup=1
args=()
for a in "$@"; do
  case $a in
    --no-setup) setup=0 ;;
    -h|--help) sed -n '2,11p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) args+=("$a") ;;
  esac
done
if [ $setup -eq 1 ]; then
  bash "$repo/deploy/install-deps.sh"
  echo "office-day: building the simulator, the behavior, the courier and the experiment"
  bash "$repo/deploy/build.sh" --target office_day_experiment
fi
export CYCLONEDDS_URI="file://$repo/deploy/dds/loopback.xml"
out="$repo/runs/office-day-$(date +%Y%m%d-%H%M%S)"
has_out=0
for a in "${args[@]}"; do [ "$a" = --out ] && has_out=1; done
[ $has_out -eq 1 ] || args+=(--out "$out")
exec "$repo/build/bin/office_day" "${args[@]}"
