#!/usr/bin/env bash
# Several hosts on one machine: each host is a Linux network namespace with one veth link to a
# bridge, its own address on a private /24, and its own nftables table for packet loss and
# partitions (the kernel here has no netem, so loss is nftables' `numgen random`). Everything a
# network NET makes is named after NET, so `down` finds and removes it all even when the state
# file is gone, and nothing outside NET's namespaces and bridge is touched.
set -euo pipefail

usage() {
  cat <<USAGE
Usage: deploy/hosts.sh up NET HOST... [--subnet N]   make hosts HOST... on network NET
       deploy/hosts.sh down NET                      remove NET: namespaces, links, bridge, state
       deploy/hosts.sh loss NET HOST PERCENT [out|in|both]
                                                     drop PERCENT % (0..100) of HOST's packets on
                                                     the wire, leaving (out), arriving (in) or
                                                     both ways (default); 0 removes the loss
       deploy/hosts.sh partition NET HOST            drop everything to and from HOST
       deploy/hosts.sh heal NET HOST                 undo partition (a loss stays as it was)
       deploy/hosts.sh status [NET]                  hosts, addresses, loss, partitions, drops
       deploy/hosts.sh exec NET HOST CMD [ARGS...]   run CMD on HOST (AUTONOMY_HOST=HOST set)
       deploy/hosts.sh run NET HOST... [--subnet N] -- CMD [ARGS...]
                                                     up, run CMD, down whatever happens
                                                     (exit, Ctrl-C, SIGTERM)

NET is 1-8 lower-case letters or digits; HOST is 1-15 letters, digits, _ or -. Host i (from 1,
in the order given) gets 10.231.N.i/24 in namespace NET-HOST, its link is called hnet0 there;
the bridge hb-NET gets 10.231.N.254 so that programs of the machine itself (a launcher, the
tests, autonomy node list) reach every host. N (1..254) is --subnet, or the first one no
interface of this machine uses. State: /run/autonomy-hosts/NET. Needs root, ip (iproute2) and
nft (nftables). Delay is not offered: without netem the kernel cannot hold packets back.
USAGE
}

state_root=/run/autonomy-hosts
die() { echo "hosts: $*" >&2; exit 2; }

need_root_and_tools() {
  [ "$(id -u)" -eq 0 ] || die "must run as root (network namespaces, links and nftables need it)"
  command -v ip >/dev/null || die "ip not found: install iproute2 (deploy/install-deps.sh)"
  command -v nft >/dev/null || die "nft not found: install nftables (deploy/install-deps.sh)"
}

check_net() { [[ "$1" =~ ^[a-z0-9]{1,8}$ ]] || die "network name '$1' must be 1-8 lower-case letters or digits"; }
check_host() { [[ "$1" =~ ^[A-Za-z0-9_-]{1,15}$ ]] || die "host name '$1' must be 1-15 letters, digits, _ or -"; }

# hosts_of NET: the hosts of a network that is up, one per line, in address order.
hosts_of() {
  [ -f "$state_root/$1/hosts" ] || die "network '$1' is not up (no $state_root/$1; up it first)"
  cat "$state_root/$1/hosts"
}

# ns_of NET HOST: the namespace of a known host; an unknown host is an error naming the known ones.
ns_of() {
  local h
  for h in $(hosts_of "$1"); do [ "$h" != "$2" ] || { echo "$1-$2"; return 0; }; done
  die "network '$1' has no host '$2' (its hosts: $(hosts_of "$1" | tr '\n' ' '))"
}

# The table of one host: loss and partition rules on its wire link (hnet0) only, so that the
# processes of one host still talk to each other over its loopback. The netdev hooks see packets
# as the link sends and receives them: a dropped packet is lost on the wire, as on a real network
# (an inet output-hook drop would instead fail the sender's sendto with EPERM).
nft_table() {
  cat <<'NFT'
table netdev autonomy_hosts {
  chain cut_out {}
  chain cut_in {}
  chain loss_out {}
  chain loss_in {}
  chain egress {
    type filter hook egress device "hnet0" priority 0; policy accept;
    jump cut_out
    jump loss_out
  }
  chain ingress {
    type filter hook ingress device "hnet0" priority 0; policy accept;
    jump cut_in
    jump loss_in
  }
}
NFT
}

# Removes everything named after NET, whatever state it is in (also half-made networks).
down_net() {
  local net=$1 ns link
  for ns in $(ip netns list 2>/dev/null | awk '{print $1}'); do
    [[ "$ns" == "$net"-* ]] || continue
    # Only namespaces this script made (it marks them) are removed.
    [ -f "$state_root/$net/hosts" ] && grep -qx "${ns#"$net"-}" "$state_root/$net/hosts" || \
      ip netns exec "$ns" nft list table netdev autonomy_hosts >/dev/null 2>&1 || continue
    # The processes still in it would keep it alive as an anonymous namespace: stop them first.
    ip netns pids "$ns" 2>/dev/null | xargs -r kill -KILL 2>/dev/null || true
    ip netns delete "$ns" 2>/dev/null || true
  done
  for link in $(ip -o link show 2>/dev/null | awk -F': ' '{print $2}' | cut -d@ -f1); do
    [[ "$link" == "hv$net-"* ]] && ip link delete "$link" 2>/dev/null || true
  done
  ip link show "hb-$net" >/dev/null 2>&1 && ip link delete "hb-$net" 2>/dev/null || true
  rm -rf "${state_root:?}/$net"
}

free_subnet() {
  local n used
  used=$(ip -4 -o addr show 2>/dev/null | awk '{print $4}')
  for n in $(seq 1 254); do
    grep -q "^10\.231\.$n\." <<<"$used" || { echo "$n"; return 0; }
  done
  die "no free 10.231.N.0/24 subnet left on this machine"
}

up_net() {
  local net=$1 subnet=$2; shift 2
  local hosts=("$@") i h ns
  [ ${#hosts[@]} -ge 1 ] || die "up needs at least one HOST"
  [ ${#hosts[@]} -le 253 ] || die "at most 253 hosts per network"
  declare -A seen=()
  for h in "${hosts[@]}"; do
    check_host "$h"
    [ -z "${seen[$h]:-}" ] || die "host '$h' is given twice"
    seen[$h]=1
  done
  [ ! -e "$state_root/$net" ] || die "network '$net' is already up (down it first: deploy/hosts.sh down $net)"
  ip link show "hb-$net" >/dev/null 2>&1 && die "bridge hb-$net exists but network '$net' has no state: deploy/hosts.sh down $net"
  [ -n "$subnet" ] || subnet=$(free_subnet)
  [[ "$subnet" =~ ^[0-9]+$ ]] && [ "$subnet" -ge 1 ] && [ "$subnet" -le 254 ] || die "--subnet must be 1..254, got '$subnet'"
  ip -4 -o addr show | awk '{print $4}' | grep -q "^10\.231\.$subnet\." && die "10.231.$subnet.0/24 is already used on this machine: choose another --subnet"
  ip link add hb-test-$$ type bridge 2>/dev/null && ip link delete hb-test-$$ || die "this kernel cannot make bridges (CONFIG_BRIDGE)"

  # A half-made network is removed again, whatever stops us (an error, Ctrl-C, SIGTERM).
  trap 'down_net "$net"; exit 130' INT TERM
  trap 'status=$?; [ $status -eq 0 ] || down_net "$net"' EXIT
  mkdir -p "$state_root/$net"
  echo "$subnet" >"$state_root/$net/subnet"
  : >"$state_root/$net/hosts"
  ip link add "hb-$net" type bridge
  ip addr add "10.231.$subnet.254/24" dev "hb-$net"
  ip link set "hb-$net" up
  i=0
  for h in "${hosts[@]}"; do
    i=$((i + 1))
    ns="$net-$h"
    echo "$h" >>"$state_root/$net/hosts"
    ip netns add "$ns" || die "cannot make namespace $ns (kernel without CONFIG_NET_NS?)"
    ip link add "hv$net-$i" type veth peer name hnet0 netns "$ns" || die "cannot make veth pair for $h (kernel without CONFIG_VETH?)"
    ip link set "hv$net-$i" master "hb-$net"
    ip link set "hv$net-$i" up
    ip -n "$ns" link set lo up
    ip -n "$ns" addr add "10.231.$subnet.$i/24" dev hnet0
    ip -n "$ns" link set hnet0 up
    # Multicast discovery (deploy/dds/hosts-multicast.xml) needs a route for 239/8 on the wire.
    ip -n "$ns" route add 224.0.0.0/4 dev hnet0
    nft_table | ip netns exec "$ns" nft -f - || die "nft cannot load a table in $ns (kernel without nf_tables, netdev egress hooks (5.16+) or numgen?)"
  done
  trap - INT TERM EXIT
  echo "hosts: network $net up on 10.231.$subnet.0/24 (bridge hb-$net 10.231.$subnet.254):"
  i=0
  for h in "${hosts[@]}"; do i=$((i + 1)); echo "  $h 10.231.$subnet.$i (namespace $net-$h)"; done
}

set_loss() {
  local net=$1 host=$2 pct=$3 dir=${4:-both} ns d
  ns=$(ns_of "$net" "$host")
  [[ "$pct" =~ ^[0-9]+$ ]] && [ "$pct" -le 100 ] || die "loss must be a whole percent 0..100, got '$pct'"
  case $dir in out|in|both) ;; *) die "direction must be out, in or both, got '$dir'" ;; esac
  for d in out in; do
    [ "$dir" = both ] || [ "$dir" = "$d" ] || continue
    ip netns exec "$ns" nft flush chain netdev autonomy_hosts "loss_$d"
    # numgen random mod 100 is uniform on 0..99: "< pct" drops pct % of the packets.
    [ "$pct" -eq 0 ] || ip netns exec "$ns" nft add rule netdev autonomy_hosts "loss_$d" meta protocol ip numgen random mod 100 '<' "$pct" counter drop
  done
}

set_cut() {
  local net=$1 host=$2 on=$3 ns d
  ns=$(ns_of "$net" "$host")
  for d in out in; do
    ip netns exec "$ns" nft flush chain netdev autonomy_hosts "cut_$d"
    [ "$on" -eq 0 ] || ip netns exec "$ns" nft add rule netdev autonomy_hosts "cut_$d" counter drop
  done
}

# rule_summary NS CHAIN: "N % (dropped P packets)", "cut (dropped P)" or "-".
rule_summary() {
  ip netns exec "$1" nft list chain netdev autonomy_hosts "$2" 2>/dev/null | awk -v chain="$2" '
    /numgen random mod 100 </ { for (i = 1; i <= NF; i++) { if ($i == "<") pct = $(i + 1); if ($i == "packets") n = $(i + 1) } }
    /counter/ && !/numgen/ { for (i = 1; i <= NF; i++) if ($i == "packets") { cut = 1; n = $(i + 1) } }
    END { if (pct != "") printf "%s%% (%d dropped)", pct, n; else if (cut) printf "all (%d dropped)", n; else printf "-" }'
}

status_net() {
  local net=$1 h ns i=0 subnet
  subnet=$(cat "$state_root/$net/subnet")
  echo "network $net: bridge hb-$net 10.231.$subnet.254/24"
  printf '  %-15s %-15s %-22s %-22s %-16s %-16s\n' HOST ADDRESS "LOSS OUT" "LOSS IN" "CUT OUT" "CUT IN"
  for h in $(hosts_of "$net"); do
    i=$((i + 1)); ns="$net-$h"
    printf '  %-15s %-15s %-22s %-22s %-16s %-16s\n' "$h" "10.231.$subnet.$i" "$(rule_summary "$ns" loss_out)" \
      "$(rule_summary "$ns" loss_in)" "$(rule_summary "$ns" cut_out)" "$(rule_summary "$ns" cut_in)"
  done
}

# Splits "NET HOST... [--subnet N] [-- CMD...]" into net, subnet, host_list, cmd.
parse_hosts_args() {
  net=$1; shift; check_net "$net"
  subnet="" host_list=() cmd=()
  while [ $# -gt 0 ]; do
    case $1 in
      --subnet) [ $# -ge 2 ] || die "--subnet needs a value"; subnet=$2; shift 2 ;;
      --) shift; cmd=("$@"); break ;;
      -*) die "unknown option $1 (see --help)" ;;
      *) host_list+=("$1"); shift ;;
    esac
  done
}

[ $# -ge 1 ] || { usage >&2; exit 2; }
verb=$1; shift
case $verb in
  -h|--help|help) usage; exit 0 ;;
esac
need_root_and_tools
case $verb in
  up)
    [ $# -ge 2 ] || die "usage: hosts.sh up NET HOST... [--subnet N]"
    parse_hosts_args "$@"
    [ ${#cmd[@]} -eq 0 ] || die "up takes no command (use run)"
    up_net "$net" "$subnet" "${host_list[@]}" ;;
  down)
    [ $# -eq 1 ] || die "usage: hosts.sh down NET"
    check_net "$1"; down_net "$1"; echo "hosts: network $1 removed" ;;
  loss)
    [ $# -ge 3 ] && [ $# -le 4 ] || die "usage: hosts.sh loss NET HOST PERCENT [out|in|both]"
    check_net "$1"; set_loss "$@" ;;
  partition)
    [ $# -eq 2 ] || die "usage: hosts.sh partition NET HOST"
    check_net "$1"; set_cut "$1" "$2" 1 ;;
  heal)
    [ $# -eq 2 ] || die "usage: hosts.sh heal NET HOST"
    check_net "$1"; set_cut "$1" "$2" 0 ;;
  status)
    if [ $# -eq 1 ]; then check_net "$1"; hosts_of "$1" >/dev/null; status_net "$1"
    else
      shopt -s nullglob
      nets=("$state_root"/*/)
      [ ${#nets[@]} -gt 0 ] || { echo "hosts: no network is up"; exit 0; }
      for d in "${nets[@]}"; do status_net "$(basename "$d")"; done
    fi ;;
  exec)
    [ $# -ge 3 ] || die "usage: hosts.sh exec NET HOST CMD [ARGS...]"
    check_net "$1"; ns=$(ns_of "$1" "$2"); h=$2; shift 2
    exec ip netns exec "$ns" env AUTONOMY_HOST="$h" "$@" ;;
  run)
    [ $# -ge 2 ] || die "usage: hosts.sh run NET HOST... [--subnet N] -- CMD [ARGS...]"
    parse_hosts_args "$@"
    [ ${#cmd[@]} -gt 0 ] || die "run needs a command after --"
    up_net "$net" "$subnet" "${host_list[@]}"
    trap 'down_net "$net"' EXIT
    trap 'exit 130' INT
    trap 'exit 143' TERM
    rc=0; "${cmd[@]}" || rc=$?
    exit $rc ;;
  *) echo "hosts: unknown command '$verb'" >&2; usage >&2; exit 2 ;;
esac
