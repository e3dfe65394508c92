#!/usr/bin/env bash
# Figures for several hosts (docs/hosts.md), side by side in one run, as root:
#   1. DDS-layer round trip (ddsperf ping/pong, 12-byte samples) and reliable throughput (ddsperf
#      pub/sub) between two hosts at 0, 10 and 30 % loss (on what each host sends) against
#      loopback;
#   2. lockstep ticks/s: the recon team (world + three behaviors, deploy/sets/recon-parallel.set's
#      missions) on one host (loopback) against four hosts (world and each robot on its own);
#   3. the time for a cut-off peer to be noticed (its lease) and to be found again after heal.
# Uses deploy/hosts.sh (network "hbench", subnet 230), removed at the end whatever happens.
#   bash bench/hosts_bench.sh [SECONDS per figure, default 5]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
secs=${1:-5}
bin=$repo/build/bin
hosts="bash $repo/deploy/hosts.sh"
net=hbench
work=$(mktemp -d)
domain=230
[ "$(id -u)" -eq 0 ] || { echo "hosts_bench: must run as root" >&2; exit 2; }
command -v ddsperf >/dev/null || { echo "hosts_bench: ddsperf not found (cyclonedds-tools)" >&2; exit 2; }
[ -x "$bin/simulator" ] && [ -x "$bin/behavior" ] || { echo "hosts_bench: build simulator and behavior first" >&2; exit 2; }
cleanup() { $hosts down $net >/dev/null 2>&1 || true; rm -rf "$work"; }
trap cleanup EXIT
trap 'exit 130' INT TERM

$hosts down $net >/dev/null 2>&1 || true
$hosts up $net a b world r1 r2 r3 --subnet 230 >/dev/null
peers=""
for i in 1 2 3 4 5 6 254; do peers+="<Peer address=\"10.231.230.$i\"/>"; done
hosts_uri="file://$repo/deploy/dds/hosts.xml,<Discovery><Peers>$peers</Peers></Discovery>"
lo_uri="file://$repo/deploy/dds/loopback.xml"

# on HOST CMD...: CMD on a host of the bench network ("-" = loopback on this machine).
on() {
  local h=$1; shift
  if [ "$h" = - ]; then CYCLONEDDS_URI=$lo_uri "$@"
  else ip netns exec "$net-$h" env CYCLONEDDS_URI="$hosts_uri" AUTONOMY_DDS_INTERFACE=hnet0 AUTONOMY_HOST="$h" "$@"; fi
}

# pingpong A B: "RTT_P50_US RTT_P99_US KSAMPLES_PER_S" between A and B.
pingpong() {
  local a=$1 b=$2 rtt thr
  on "$b" ddsperf -D $((secs + 3)) -i $domain pong >/dev/null 2>&1 &
  local pong=$!
  rtt=$(on "$a" ddsperf -D "$secs" -i $domain -Q minmatch:1 -Q initwait:20 ping 2>&1 |
    awk '/ 50% /{for(i=1;i<=NF;i++){if($i=="50%")p=$(i+1);if($i=="99%")q=$(i+1)}} END{gsub("us","",p);gsub("us","",q);printf "%.0f %.0f", 2*p, 2*q}')
  wait $pong 2>/dev/null || true
  on "$b" ddsperf -D $((secs + 3)) -i $domain sub >"$work/sub.out" 2>&1 &
  local sub=$!
  on "$a" ddsperf -D "$secs" -i $domain -Q minmatch:1 -Q initwait:20 pub >/dev/null 2>&1 || true
  wait $sub 2>/dev/null || true
  thr=$(awk '/ rate /{for(i=1;i<=NF;i++) if($i=="rate") r=$(i+1)} END{print r+0}' "$work/sub.out")
  echo "$rtt $thr"
}

echo "== 1. DDS layer between two hosts (ddsperf, ${secs} s each; RTT = 2 x ddsperf's one-way figure)"
read -r lo_p50 lo_p99 lo_thr <<<"$(pingpong - -)"
printf '%-22s %10s %10s %14s %16s\n' "" "RTT p50 us" "RTT p99 us" "throughput kS/s" "vs loopback"
printf '%-22s %10s %10s %14s %16s\n' "loopback" "$lo_p50" "$lo_p99" "$lo_thr" "1.00 / 1.00"
for loss in 0 10 30; do
  $hosts loss $net a "$loss" out; $hosts loss $net b "$loss" out
  read -r p50 p99 thr <<<"$(pingpong a b)"
  printf '%-22s %10s %10s %14s %16s\n' "two hosts, $loss % loss" "$p50" "$p99" "$thr" \
    "$(awk -v a="$p50" -v b="$lo_p50" -v c="$thr" -v d="$lo_thr" 'BEGIN{printf "%.2f / %.2f", a/b, (d>0?c/d:0)}')"
done
$hosts loss $net a 0; $hosts loss $net b 0

# team HOSTS...: ticks/s of the recon team in lockstep with the world and r1..r3 on these hosts.
team() {
  local w=$1 h1=$2 h2=$3 h3=$4 start end ticks
  start=$(date +%s.%N)
  on "$w" "$bin/simulator" --config "$repo/deploy/scenarios/recon.pbtxt" --without-robots --mode lockstep \
    --stop-when-finished --max-ticks 200000 --wait-for behavior/r1 --wait-for behavior/r2 --wait-for behavior/r3 \
    --domain $domain --log-dir "$work" >"$work/sim.out" 2>&1 &
  local sim=$! pids=()
  on "$h1" "$bin/behavior" --robot r1 --mission "$repo/deploy/missions/comm_parallel_r1.pbtxt" --start 40 3 --resolution 1 --domain $domain --log-dir "$work" >/dev/null 2>&1 & pids+=($!)
  on "$h2" "$bin/behavior" --robot r2 --mission "$repo/deploy/missions/comm_parallel_r2.pbtxt" --start 125 3 --resolution 1 --domain $domain --log-dir "$work" >/dev/null 2>&1 & pids+=($!)
  on "$h3" "$bin/behavior" --robot r3 --mission "$repo/deploy/missions/comm_parallel_r3.pbtxt" --start 210 3 --resolution 1 --domain $domain --log-dir "$work" >/dev/null 2>&1 & pids+=($!)
  wait $sim || true
  end=$(date +%s.%N)
  kill "${pids[@]}" 2>/dev/null || true; wait "${pids[@]}" 2>/dev/null || true
  ticks=$(sed -n 's/.*stopped at tick \([0-9]*\):.*/\1/p' "$work/sim.out" | tail -1)
  awk -v t="$ticks" -v s="$start" -v e="$end" 'BEGIN{printf "%d %.1f %.0f", t, e-s, t/(e-s)}'
}
echo
echo "== 2. Lockstep: the recon team to the end of its missions (wall time includes start-up)"
read -r t1 s1 r1 <<<"$(team - - - -)"
read -r t4 s4 r4 <<<"$(team world r1 r2 r3)"
$hosts loss $net world 10 out; for h in r1 r2 r3; do $hosts loss $net $h 10 out; done
read -r t5 s5 r5 <<<"$(team world r1 r2 r3)"
for h in world r1 r2 r3; do $hosts loss $net $h 0; done
printf '%-30s %8s %8s %10s %12s\n' "" ticks "wall s" "ticks/s" "vs one host"
printf '%-30s %8s %8s %10s %12s\n' "one host (loopback)" "$t1" "$s1" "$r1" 1.00
printf '%-30s %8s %8s %10s %12s\n' "four hosts" "$t4" "$s4" "$r4" "$(awk -v a="$r4" -v b="$r1" 'BEGIN{printf "%.2f", a/b}')"
printf '%-30s %8s %8s %10s %12s\n' "four hosts, 10 % loss" "$t5" "$s5" "$r5" "$(awk -v a="$r5" -v b="$r1" 'BEGIN{printf "%.2f", a/b}')"

echo
echo "== 3. A peer cut off (partition) and healed: seconds until DDS notices (lease 3 s) and finds it again"
stamp() { while IFS= read -r line; do echo "$(date +%s.%N) $line"; done; }
on b ddsperf -D 40 -i $domain pong >/dev/null 2>&1 &
pong=$!
on a ddsperf -D 38 -i $domain ping 2>&1 | stamp >"$work/ping.out" &
sleep 4
cut=$(date +%s.%N); $hosts partition $net b
sleep 8
heal=$(date +%s.%N); $hosts heal $net b
sleep 8
kill $pong 2>/dev/null || true
gone=$(awk -v t="$cut" '$0 ~ /participant .*: gone/ && $1 > t {print $1; exit}' "$work/ping.out")
back=$(awk -v t="$heal" '$0 ~ /participant .*: new/ && $1 > t {print $1; exit}' "$work/ping.out")
awk -v c="$cut" -v g="${gone:-0}" -v h="$heal" -v b="${back:-0}" 'BEGIN{
  printf "noticed cut off after  %s s\n", (g > 0 ? sprintf("%.1f", g - c) : "never (within 8 s)");
  printf "found again after heal %s s\n", (b > 0 ? sprintf("%.1f", b - h) : "never (within 8 s)") }'
wait 2>/dev/null || true
