#!/usr/bin/env bash
# Starts a service set, waits until every process reports ready through its heartbeat, then
# supervises it: a process that ends, or hangs (no heartbeat for its hang limit), is reported
# (exit code or signal, the last lines of its output) and handled by its on-exit policy (stop the
# set, respawn it with a back-off, or ignore it). The launcher owns the run: Ctrl-C, SIGTERM or `launch.sh stop RUN_DIR` from another
# terminal make it stop the whole set and end. With --detach the launcher itself goes to the
# background (its pid in RUN_DIR/launch.pid, its reports in RUN_DIR/launch.log).
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
self="$repo/deploy/launch.sh"

usage() {
  cat <<USAGE
Usage: deploy/launch.sh [options] SET        start service set SET (deploy/sets/SET.set, or a
                                             path to a .set file)
       deploy/launch.sh stop RUN_DIR         stop the set running in RUN_DIR (from any terminal)
       deploy/launch.sh --list               list the service sets

Every process of the set runs in its own session with its output in RUN_DIR/NAME.out and its pid
in RUN_DIR/NAME.pid (NAME with / as -). The launcher waits until each one's heartbeat says ready
(autonomy node wait --pid: the heartbeat of the pid it started, so a process of the same name from
another set on the domain is never taken for its own) and its liveliness watcher (below) has heard
it, prints "launch: set 'SET' ready", then supervises the set:
  - by default in the foreground; Ctrl-C, SIGTERM, SIGHUP (the terminal closed) or
    'launch.sh stop RUN_DIR' from another terminal stop the whole set, and the launcher ends
    (exit code 0);
  - with --detach it goes to the background and this command returns once the set is ready.
    The detached launcher supervises the set the same way; its reports go to RUN_DIR/launch.log.
    'launch.sh stop RUN_DIR' ends it and the set.
The launcher's pid is in RUN_DIR/launch.pid. 'stop' sends it SIGTERM and waits for it to end; when
no launcher is alive (it was killed) 'stop' stops the processes of the pid files itself.
Stopping sends SIGINT (and SIGCONT, for a paused one) to every process, waits up to 10 s, then
SIGKILLs what is left; a process whose launcher dies anyhow (even kill -9) gets SIGTERM from the
kernel: no orphans either way.

When a process of the set ends while the set runs, the launcher reports it: its name and pid,
"exit code N" or "killed by SIGNAME" (a program's own exit code above 128 reads as a signal),
how long it ran, and the last 10 lines of its output. Then its on-exit policy decides:
  on-exit=stop       (default) stop the whole set; the launcher ends with exit code 1
  on-exit=ignore     leave it ended; the rest of the set goes on (the launcher ends, with 0,
                     when no process is left)
  on-exit=respawn[:max=N][:backoff=S]
                     start it again after S seconds (default 1), doubling for each further
                     respawn (at most 60 s), at most N times (default 3; a run of 60 s or more
                     before it ended starts the count afresh); then stop the set as 'stop' does.
                     The new process gets a new pid file, its output is appended to NAME.out,
                     and its readiness is checked again (autonomy node wait, --timeout).
A process that ends before the set is ready is handled the same way.

A process that stops answering is noticed too. The launcher runs 'autonomy node watch' on the
set (its events in RUN_DIR/launch.watch), which follows every process's heartbeat (each one
publishes every --heartbeat-period, 0.5 s by default):
  - not heard for 3 heartbeat periods (at least 1 s), or its DDS lease expired: reported as
    silent ("launch: NAME (pid P) is silent: ..."); heard again before its hang limit: reported
    and left alone (a SIGSTOP followed by SIGCONT, a long pause);
  - silent for its hang limit (default 10 s; --hang-after S for every process, hang-after=S on
    a line for that one; 0 turns it off): reported as hung with the last 10 lines of its output,
    then its on-exit policy applies: respawn kills it (SIGKILL) and starts it again exactly as
    after an exit (same count and back-off); stop kills it and stops the set (exit code 1);
    ignore only reports it.
When a respawned process is ready, the launcher says "launch: set 'SET' ready again".
The watcher also reports the simulator's lockstep drops ("launch: the simulator dropped NAME from
lockstep at tick T: REASON") and rejoins ("launch: NAME is back in lockstep at tick T: REASON").
While a process is silent, 'autonomy node list' shows it as stale (the watcher republishes its
last heartbeat), also in a listing started after it went silent.

Options:
  --domain N        DDS domain id (default: \$AUTONOMY_DOMAIN or 0)
  --profile P       Cyclone DDS profile: loopback (default), lan, secure, or a path to an XML file.
                    With lan, AUTONOMY_PEERS="host1 host2" adds unicast peers. secure is loopback
                    with DDS Security: each process gets the identity of its NAME from
                    \$AUTONOMY_SECURITY_DIR (default runs/security; missing ones are made there
                    with deploy/security/security.sh, all are checked first; docs/security.md).
  --run-dir DIR     run folder (default: runs/SET-<date>-<time> in the repository)
  --bin DIR         folder of the programs (default: build/bin in the repository)
  --timeout S       seconds to wait for readiness (default 20), also after a respawn
  --hang-after S    seconds without a heartbeat after which a process is hung (default 10;
                    0: never); a set line's hang-after=S wins
  --detach          start, wait until ready, return; the launcher supervises in the background
  --hosts NET       the set runs on the hosts of network NET (deploy/hosts.sh up NET ...): a
                    line NAME@HOST starts its process in HOST's namespace (AUTONOMY_HOST=HOST,
                    which its heartbeat reports), a line without @HOST on this machine (on the
                    bridge). The profile defaults to hosts (deploy/dds/hosts.xml, every host's
                    address a unicast peer); RUN_DIR/dds.env has the settings for tools such as
                    autonomy node list (docs/hosts.md). The processes of a host are supervised
                    from that host: their readiness check and their liveliness watcher run in
                    its namespace (RUN_DIR/launch.watch.HOST), so a host cut off from this
                    machine longer than the hang limit is not respawned (its processes still
                    answer there); this machine's watcher only reports what it cannot hear
  -h, --help        this text

A set file has one process per line:
  NAME[@HOST] [on-exit=POLICY] [hang-after=S] PROGRAM [ARGS...]
NAME is service/instance as its heartbeat reports it (service alone means service/main), PROGRAM
a program in the --bin folder. Lines starting with # are comments. {run} in an argument stands
for the run folder, {repo} for the repository. launch.sh adds --domain and --log-dir RUN_DIR to
each. Mistakes (unknown program or policy, a bad hang-after, a NAME twice) are reported as
FILE:LINE before anything starts.
USAGE
}

list_sets() { for f in "$repo"/deploy/sets/*.set; do basename "$f" .set; done; }

# describe_exit STATUS: how a process ended, from the status bash's wait returns.
describe_exit() {
  local status=$1 sig
  if [ "$status" -gt 128 ] && sig=$(kill -l $((status - 128)) 2>/dev/null); then
    echo "killed by SIG$sig"
  else
    echo "exit code $status"
  fi
}

# is_running PID: the process exists and has not ended (an ended process whose parent has not
# collected it yet, a zombie, has ended).
is_running() {
  local state
  state=$(sed -n 's/^.*) \(.\).*$/\1/p' "/proc/$1/stat" 2>/dev/null) || return 1
  [ -n "$state" ] && [ "$state" != Z ] && [ "$state" != X ]
}

# stop_processes RUN_DIR: SIGINT to every process of the pid files, SIGKILL after 10 s.
stop_processes() {
  local run_dir=$1 pid name deadline alive f
  shopt -s nullglob
  local pidfiles=("$run_dir"/*.pid)
  local targets=()
  for f in "${pidfiles[@]}"; do [ "$(basename "$f")" = launch.pid ] || targets+=("$f"); done
  [ ${#targets[@]} -gt 0 ] || return 0
  # SIGCONT too: a process paused (SIGSTOP) would otherwise sit on its SIGINT until the SIGKILL.
  for f in "${targets[@]}"; do
    pid=$(cat "$f")
    kill -INT "$pid" 2>/dev/null || true
    kill -CONT "$pid" 2>/dev/null || true
  done
  deadline=$((SECONDS + 10))
  while :; do
    alive=0
    for f in "${targets[@]}"; do is_running "$(cat "$f")" && alive=1; done
    [ $alive -eq 0 ] && break
    if [ $SECONDS -ge $deadline ]; then
      for f in "${targets[@]}"; do
        pid=$(cat "$f"); name=$(basename "$f" .pid)
        if is_running "$pid"; then
          echo "launch: $name (pid $pid) ignored SIGINT for 10 s: killing it" >&2
          kill -KILL "$pid" 2>/dev/null || true
        fi
      done
      break
    fi
    sleep 0.1
  done
  rm -f "${targets[@]}"
}

# launcher_of RUN_DIR: the pid of the launcher that owns the run, if it is alive.
launcher_of() {
  local pid
  pid=$(cat "$1/launch.pid" 2>/dev/null) || return 1
  [[ "$pid" =~ ^[0-9]+$ ]] && is_running "$pid" || return 1
  # The pid may have been reused by another program since: it must be a launch.sh.
  tr '\0' ' ' <"/proc/$pid/cmdline" | grep -q "launch\.sh" || return 1
  echo "$pid"
}

# stop_run RUN_DIR: 'launch.sh stop'. The launcher that owns the run stops its set and ends;
# without one, the processes of the pid files are stopped here.
stop_run() {
  local run_dir=$1 pid deadline
  [ -d "$run_dir" ] || { echo "launch: stop: no run folder $run_dir" >&2; return 2; }
  if pid=$(launcher_of "$run_dir"); then
    kill -TERM "$pid" 2>/dev/null || true
    # Its own stop takes at most 10 s (then SIGKILL); a few more for the reporting.
    deadline=$((SECONDS + 15))
    while is_running "$pid" && [ $SECONDS -lt $deadline ]; do sleep 0.1; done
    if ! is_running "$pid"; then
      echo "launch: stopped the set in $run_dir (its launcher, pid $pid, has ended)"
      return 0
    fi
    echo "launch: the launcher (pid $pid) did not end within 15 s; stopping its processes here" >&2
  fi
  shopt -s nullglob
  local pidfiles=("$run_dir"/*.pid)
  [ ${#pidfiles[@]} -gt 0 ] || { echo "launch: nothing runs in $run_dir (no launcher, no pid files)" >&2; return 1; }
  stop_processes "$run_dir"
  rm -f "$run_dir/launch.pid"
  echo "launch: stopped the set in $run_dir"
}

domain=${AUTONOMY_DOMAIN:-0}
profile=loopback
run_dir=""
bin="$repo/build/bin"
timeout=20
hang_after=10
detach=0
hosts_net=""
set_arg=""
# Set by a launcher for the copy of itself it leaves in the background (--detach).
detached_launcher=${AUTONOMY_LAUNCH_DETACHED:-}
unset AUTONOMY_LAUNCH_DETACHED

need_value() { [ $# -ge 2 ] || { echo "launch: $1 needs a value (see --help)" >&2; exit 2; }; }
while [ $# -gt 0 ]; do
  case $1 in
    -h|--help) usage; exit 0 ;;
    --list) list_sets; exit 0 ;;
    --domain) need_value "$@"; domain=$2; shift 2 ;;
    --profile) need_value "$@"; profile=$2; shift 2 ;;
    --run-dir) need_value "$@"; run_dir=$2; shift 2 ;;
    --bin) need_value "$@"; bin=$2; shift 2 ;;
    --timeout) need_value "$@"; timeout=$2; shift 2 ;;
    --hang-after) need_value "$@"; hang_after=$2; shift 2 ;;
    --detach) detach=1; shift ;;
    --hosts) need_value "$@"; hosts_net=$2; shift 2 ;;
    stop)
      [ $# -eq 2 ] || { echo "launch: usage: launch.sh stop RUN_DIR" >&2; exit 2; }
      rc=0; stop_run "$2" || rc=$?; exit $rc ;;
    -*) echo "launch: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) [ -z "$set_arg" ] || { echo "launch: one set at a time ($set_arg, $1)" >&2; exit 2; }
       set_arg=$1; shift ;;
  esac
done

[ -n "$set_arg" ] || { usage >&2; exit 2; }
if [[ "$set_arg" == */* || "$set_arg" == *.set ]]; then
  set_file=$set_arg
  [ -f "$set_file" ] || { echo "launch: set file $set_file not found" >&2; exit 2; }
else
  set_file="$repo/deploy/sets/$set_arg.set"
  [ -f "$set_file" ] || { echo "launch: no service set '$set_arg'; known sets: $(list_sets | tr '\n' ' ')" >&2; exit 2; }
fi
set_file="$(cd "$(dirname "$set_file")" && pwd)/$(basename "$set_file")"
set_name=$(basename "$set_file" .set)
[[ "$domain" =~ ^[0-9]+$ ]] && [ "$domain" -le 232 ] || { echo "launch: --domain must be 0..232, got '$domain'" >&2; exit 2; }
[[ "$timeout" =~ ^[0-9]+([.][0-9]+)?$ ]] || { echo "launch: --timeout must be a number of seconds, got '$timeout'" >&2; exit 2; }
[[ "$hang_after" =~ ^[0-9]+([.][0-9]+)?$ ]] || { echo "launch: --hang-after must be a number of seconds (0: never), got '$hang_after'" >&2; exit 2; }
[ -d "$bin" ] || { echo "launch: --bin $bin is not a folder" >&2; exit 2; }
bin=$(cd "$bin" && pwd)
[ -x "$bin/autonomy" ] || { echo "launch: $bin/autonomy not found: build first (bash deploy/build.sh --demo)" >&2; exit 2; }

security_dir=""
case $profile in
  loopback|lan|hosts|hosts-multicast) uri="file://$repo/deploy/dds/$profile.xml" ;;
  # Loopback with DDS Security: every process gets its own identity (docs/security.md).
  secure) uri="file://$repo/deploy/dds/loopback.xml"
     security_dir=${AUTONOMY_SECURITY_DIR:-$repo/runs/security} ;;
  *) [ -f "$profile" ] || { echo "launch: profile file $profile not found" >&2; exit 2; }
     profile="$(cd "$(dirname "$profile")" && pwd)/$(basename "$profile")"
     uri="file://$profile" ;;
esac
if [ "$profile" = lan ] && [ -n "${AUTONOMY_PEERS:-}" ]; then
  peers=""
  for p in $AUTONOMY_PEERS; do peers+="<Peer address=\"$p\"/>"; done
  uri+=",<Discovery><Peers>$peers</Peers></Discovery>"
fi
# Several hosts (deploy/hosts.sh): processes of this machine talk on the network's bridge, those
# of a host on its link (hnet0, set per process); every host is a peer.
hosts_state=/run/autonomy-hosts/$hosts_net
declare -A host_known=()
if [ -n "$hosts_net" ]; then
  [ -f "$hosts_state/hosts" ] || { echo "launch: --hosts $hosts_net: no such network is up (deploy/hosts.sh up $hosts_net HOST...)" >&2; exit 2; }
  [[ "$profile" != loopback && "$profile" != secure ]] || { profile=hosts; uri="file://$repo/deploy/dds/hosts.xml"; }
  subnet=$(cat "$hosts_state/subnet")
  peers="<Peer address=\"10.231.$subnet.254\"/>"
  host_index=0
  while read -r h; do
    host_index=$((host_index + 1)); host_known[$h]=1
    peers+="<Peer address=\"10.231.$subnet.$host_index\"/>"
  done <"$hosts_state/hosts"
  [[ "$profile" == hosts-multicast ]] || uri+=",<Discovery><Peers>$peers</Peers></Discovery>"
  export AUTONOMY_DDS_INTERFACE=hb-$hosts_net
fi
export CYCLONEDDS_URI=$uri
export AUTONOMY_DOMAIN=$domain

[ -n "$run_dir" ] || run_dir="$repo/runs/$set_name-$(date +%Y%m%d-%H%M%S)"
mkdir -p "$run_dir"
run_dir=$(cd "$run_dir" && pwd)
if pid=$(launcher_of "$run_dir") && [ "$pid" != $$ ]; then
  echo "launch: $run_dir is the run of a launcher still alive (pid $pid): stop it first" >&2
  exit 2
fi

# ---- The set file, checked whole before anything starts.
names=() hosts=() files=() programs=() commands=() policies=() max_respawns=() backoffs=() hang_afters=()
declare -A line_of_name=()
line_no=0
set_error() { echo "launch: $set_file:$line_no: $*" >&2; exit 2; }
while IFS= read -r line || [ -n "$line" ]; do
  line_no=$((line_no + 1))
  line=${line%%#*}
  read -r -a words <<<"$line" || true
  [ ${#words[@]} -gt 0 ] || continue
  name=${words[0]} host=""
  if [[ "$name" == *@* ]]; then
    host=${name#*@}; name=${name%%@*}
    [ -n "$hosts_net" ] || set_error "$name@$host names a host: start the set with --hosts NET (deploy/hosts.sh)"
    [ -n "${host_known[$host]:-}" ] || set_error "network $hosts_net has no host '$host' (its hosts: $(tr '\n' ' ' <"$hosts_state/hosts"))"
  fi
  [[ "$name" =~ ^[A-Za-z0-9_.-]+(/[A-Za-z0-9_.-]+)?$ ]] || set_error "'$name' is not a NAME (service/instance, letters, digits, _ . -)"
  [[ "$name" == */* ]] || name="$name/main"
  [ -z "${line_of_name[$name]:-}" ] || set_error "$name is already line ${line_of_name[$name]}'s process"
  line_of_name[$name]=$line_no
  policy=stop max=3 backoff=1 hang=$hang_after seen_policy=0 seen_hang=0
  rest=("${words[@]:1}")
  while [ ${#rest[@]} -gt 0 ] && [[ "${rest[0]}" == on-exit=* || "${rest[0]}" == hang-after=* ]]; do
    if [[ "${rest[0]}" == hang-after=* ]]; then
      [ $seen_hang -eq 0 ] || set_error "hang-after is given twice"
      seen_hang=1
      hang=${rest[0]#hang-after=}
      rest=("${rest[@]:1}")
      [[ "$hang" =~ ^[0-9]+([.][0-9]+)?$ ]] || set_error "hang-after must be seconds (0: never), got '$hang'"
      continue
    fi
    [ $seen_policy -eq 0 ] || set_error "on-exit is given twice"
    seen_policy=1
    spec=${rest[0]#on-exit=}
    rest=("${rest[@]:1}")
    IFS=: read -r -a parts <<<"$spec"
    case ${parts[0]:-} in
      stop|ignore) policy=${parts[0]}
        [ ${#parts[@]} -eq 1 ] || set_error "on-exit=${parts[0]} takes no options (only respawn has max= and backoff=)" ;;
      respawn) policy=respawn
        for opt in "${parts[@]:1}"; do
          case $opt in
            max=*) max=${opt#max=}
              [[ "$max" =~ ^[0-9]+$ ]] && [ "$max" -ge 1 ] && [ "$max" -le 1000 ] || set_error "respawn max must be 1..1000, got '$max'" ;;
            backoff=*) backoff=${opt#backoff=}
              [[ "$backoff" =~ ^[0-9]+([.][0-9]+)?$ ]] && [ "$(awk -v b="$backoff" 'BEGIN{print (b > 0 && b <= 60)}')" = 1 ] \
                || set_error "respawn backoff must be seconds in (0, 60], got '$backoff'" ;;
            *) set_error "unknown respawn option '$opt' (max=N, backoff=S)" ;;
          esac
        done ;;
      *) set_error "unknown on-exit policy '$spec' (stop, ignore, respawn[:max=N][:backoff=S])" ;;
    esac
  done
  [ ${#rest[@]} -ge 1 ] || set_error "expected NAME [on-exit=POLICY] [hang-after=S] PROGRAM [ARGS...]"
  program=${rest[0]}
  [[ "$program" != */* ]] || set_error "PROGRAM is a name in the --bin folder, not a path: '$program'"
  [ -x "$bin/$program" ] || set_error "program $bin/$program not found"
  command=""
  for w in "${rest[@]:1}"; do
    w="${w//\{run\}/$run_dir}"
    command+="$(printf '%q' "${w//\{repo\}/$repo}") "
  done
  names+=("$name"); hosts+=("$host"); files+=("${name//\//-}"); programs+=("$program"); commands+=("$command")
  policies+=("$policy"); max_respawns+=("$max"); backoffs+=("$backoff"); hang_afters+=("$hang")
done <"$set_file"
[ ${#names[@]} -gt 0 ] || { echo "launch: $set_file has no process" >&2; exit 2; }
# Secured: identities for the set's processes and the launcher's tools (operator: the watcher
# republishes silent heartbeats) are made where missing and checked before anything starts.
if [ -n "$security_dir" ]; then
  bash "$repo/deploy/security/security.sh" set "$security_dir" "$set_file" || { echo "launch: the set's DDS Security identities in $security_dir are not usable (above)" >&2; exit 2; }
  [ "$domain" -le 230 ] || { echo "launch: --profile secure needs --domain 0..230 (Cyclone's governance covers no more)" >&2; exit 2; }
  security_dir=$(cd "$security_dir" && pwd)
fi
# with_identity NAME: CYCLONEDDS_URI for a process of identity NAME (unchanged when not secured).
with_identity() {
  if [ -n "$security_dir" ]; then echo "$uri,file://$security_dir/identities/${1//\//-}/cyclone.xml"; else echo "$uri"; fi
}

# ---- Detached: the same launcher in the background, in its own session; this one returns when
# the set is ready (exit 0) or the launcher gave up (exit 1, its report printed).
if [ $detach -eq 1 ]; then
  rm -f "$run_dir/launch.state"
  AUTONOMY_LAUNCH_DETACHED=1 setsid bash "$self" --domain "$domain" --profile "$profile" --run-dir "$run_dir" --bin "$bin" ${hosts_net:+--hosts "$hosts_net"} \
    --timeout "$timeout" --hang-after "$hang_after" "$set_file" >"$run_dir/launch.log" 2>&1 </dev/null &
  launcher=$!
  trap 'kill -TERM $launcher 2>/dev/null; wait $launcher 2>/dev/null; cat "$run_dir/launch.log"; exit 130' INT TERM
  state=""
  while is_running $launcher; do
    state=$(cat "$run_dir/launch.state" 2>/dev/null || true)
    [ "$state" != ready ] || break
    sleep 0.1
  done
  cat "$run_dir/launch.log"
  if [ "$state" = ready ]; then
    echo "launch: detached; the launcher (pid $launcher) supervises the set, reports in $run_dir/launch.log"
    echo "launch: stop it with: deploy/launch.sh stop $run_dir"
    exit 0
  fi
  echo "launch: the set did not start (report above, also in $run_dir/launch.log)" >&2
  exit 1
fi

# ---- The launcher: starts the set and supervises it until it is stopped.
echo $$ >"$run_dir/launch.pid"
# What a tool of this machine needs to join the set's DDS traffic (autonomy node list, topic echo).
printf 'export CYCLONEDDS_URI=%q AUTONOMY_DOMAIN=%q%s\n' "$CYCLONEDDS_URI" "$domain" \
  "${AUTONOMY_DDS_INTERFACE:+ AUTONOMY_DDS_INTERFACE=$AUTONOMY_DDS_INTERFACE}" >"$run_dir/dds.env"
set_state() { echo "$1" >"$run_dir/launch.state"; }
set_state starting

declare -A index_of_pid=()   # pid of a set process -> its index
declare -A respawn_timer=()  # pid of a back-off sleep -> index of the process it respawns
declare -A ready_check=()    # pid of an 'autonomy node wait' -> index of the process it awaits
declare -A index_of_name=()  # NAME -> its index
started_at=() respawn_count=() ready=() gone=() pid_of=() killed_hung=()
# A process is ready when its heartbeat said so (ready_seen: autonomy node wait) and the watcher
# has heard it (watched), so that it cannot hang unnoticed from then on.
ready_seen=() watched=()
set_ready=0
stop_request=""
stopped=0
for i in "${!names[@]}"; do index_of_name[${names[$i]}]=$i; killed_hung[$i]=0; done
# The liveliness watchers (autonomy node watch) append their events to their files; the loop reads
# them every tick (a short sleep child, so that 'wait -n' also wakes for them). One watcher runs on
# this machine (group "-": RUN_DIR/launch.watch) and, with --hosts, one inside each host's
# namespace for the processes of that host (group HOST: RUN_DIR/launch.watch.HOST). A process is
# judged (ready, silent, hung) by the watcher of its own host only: a host cut off from this
# machine (a partition) does not make its processes hung, its own watcher still hears them. The
# machine's watcher also reports what this machine does not hear and the simulator's lockstep drops.
declare -A watch_file_of=() watch_fd_of=() watch_rest_of=() watch_pid_of=()  # group -> ...
declare -A watch_group_of_pid=() watch_restart_of_pid=()  # watcher (or its restart timer) pid -> group
watch_groups=(-)
tick=""
this_host=$(uname -n)

# start_process I [respawn]: starts process I in its own session (SIGTERM reaches it when this
# launcher dies, however it dies) and the check that it becomes ready.
start_process() {
  local i=$1 file=${files[$1]} pid
  local -a args
  eval "args=(${commands[$i]})"
  if [ "${2:-}" = respawn ]; then
    echo "=== launch: respawn ${respawn_count[$i]} at $(date +%T)" >>"$run_dir/$file.out"
  else
    : >"$run_dir/$file.out"
  fi
  # On a host: inside its namespace, naming the host (the namespace has this machine's hostname).
  local -a on_host=()
  [ -z "${hosts[$i]}" ] || on_host=(ip netns exec "$hosts_net-${hosts[$i]}" env AUTONOMY_HOST="${hosts[$i]}" AUTONOMY_DDS_INTERFACE=hnet0)
  CYCLONEDDS_URI=$(with_identity "${names[$i]}") setpriv --pdeathsig TERM setsid "${on_host[@]}" "$bin/${programs[$i]}" "${args[@]}" --domain "$domain" --log-dir "$run_dir" \
    >>"$run_dir/$file.out" 2>&1 </dev/null &
  pid=$!
  echo $pid >"$run_dir/$file.pid"
  index_of_pid[$pid]=$i
  pid_of[$i]=$pid
  killed_hung[$i]=0
  started_at[$i]=$SECONDS
  ready[$i]=0 ready_seen[$i]=0 watched[$i]=0
  echo "launch: started ${names[$i]}${hosts[$i]:+ on ${hosts[$i]}} (pid $pid): ${programs[$i]} ${args[*]}"
  # --pid: only this child's heartbeat counts, not a process of the same name from another set.
  # The heartbeat awaited names the process's host; node wait compares it with its own.
  # On a host, it waits there: a host cut off from this machine still hears its own processes.
  AUTONOMY_HOST=${hosts[$i]:-${AUTONOMY_HOST:-}} CYCLONEDDS_URI=$(with_identity operator) "${on_host[@]}" "$bin/autonomy" node wait --domain "$domain" --timeout "$timeout" --pid "$pid" "${names[$i]}" &
  ready_check[$!]=$i
}

# stop_set: the timers and readiness checks first (no respawn during the stop), then the set.
stop_set() {
  [ $stopped -eq 0 ] || return 0
  stopped=1
  set_state stopping
  local pid
  for pid in "${!respawn_timer[@]}" "${!ready_check[@]}" "${!watch_group_of_pid[@]}" "${!watch_restart_of_pid[@]}" $tick; do
    kill -TERM "$pid" 2>/dev/null || true
  done
  stop_processes "$run_dir"
  wait 2>/dev/null || true
  set_state stopped
  rm -f "$run_dir/launch.pid"
  echo "launch: stopped the set in $run_dir"
}

print_tail() {
  local out="$run_dir/$1.out"
  echo "launch: last lines of $out:"
  tail -n 10 "$out" 2>/dev/null | sed 's/^/  | /'
}

# check_set_ready: once every process that is expected to run is ready, say so (once).
check_set_ready() {
  local i without=""
  [ $set_ready -eq 0 ] || return 0
  for i in "${!names[@]}"; do
    if [ "${gone[$i]:-0}" -eq 1 ]; then without+=" ${names[$i]}"; continue; fi
    [ "${ready[$i]}" -eq 1 ] || return 0
  done
  set_ready=1
  set_state ready
  echo "launch: set '$set_name' ready on domain $domain; logs in $run_dir${without:+ (without$without, which ended)}"
  if [ -z "$detached_launcher" ]; then
    echo "launch: Ctrl-C stops the set; so does, from another terminal: deploy/launch.sh stop $run_dir"
  fi
}

# process_ended I STATUS PID: report, then the process's on-exit policy.
process_ended() {
  local i=$1 status=$2 name=${names[$1]} ran delay n pid
  ran=$((SECONDS - started_at[$i]))
  rm -f "$run_dir/${files[$i]}.pid"
  # Its readiness check has nothing left to wait for.
  for pid in "${!ready_check[@]}"; do
    [ "${ready_check[$pid]}" != "$i" ] || { kill -TERM "$pid" 2>/dev/null || true; unset "ready_check[$pid]"; }
  done
  if [ "${killed_hung[$i]}" -eq 1 ]; then
    # Its report and last lines came when it was found hung.
    echo "launch: $name (pid $3) ended: $(describe_exit "$status") by the launcher (hung) after $ran s"
  else
    echo "launch: $name (pid $3) ended: $(describe_exit "$status") after $ran s"
    print_tail "${files[$i]}"
  fi
  case ${policies[$i]} in
    ignore)
      gone[$i]=1
      echo "launch: $name: on-exit=ignore, the rest of the set goes on"
      check_set_ready ;;
    stop)
      echo "launch: $name: on-exit=stop, stopping the set"
      stop_set; exit 1 ;;
    respawn)
      [ "$ran" -lt 60 ] || respawn_count[$i]=0
      n=${respawn_count[$i]:-0}
      if [ "$n" -ge "${max_respawns[$i]}" ]; then
        echo "launch: $name: no respawn left (max=${max_respawns[$i]} reached), stopping the set"
        stop_set; exit 1
      fi
      respawn_count[$i]=$((n + 1))
      delay=$(awk -v b="${backoffs[$i]}" -v n="$n" 'BEGIN { d = b * 2 ^ n; if (d > 60) d = 60; print d }')
      echo "launch: $name: respawning in $delay s (respawn $((n + 1)) of at most ${max_respawns[$i]})"
      sleep "$delay" &
      respawn_timer[$!]=$i ;;
  esac
}

# ready_checked I STATUS: the readiness check of process I ended.
ready_checked() {
  local i=$1
  if [ "$2" -eq 0 ]; then
    ready_seen[$i]=1
    became_ready "$i"
  elif [ $set_ready -eq 0 ]; then
    echo "launch: ${names[$i]} did not become ready within $timeout s, stopping the set"
    print_tail "${files[$i]}"
    stop_set; exit 1
  else
    echo "launch: ${names[$i]} was respawned but is not ready within $timeout s; it keeps running"
    print_tail "${files[$i]}"
  fi
}

# became_ready I: once process I's heartbeat said ready and the watcher heard it, it is ready.
became_ready() {
  local i=$1
  [ "${ready_seen[$i]}" -eq 1 ] && [ "${watched[$i]}" -eq 1 ] && [ "${ready[$i]}" -eq 0 ] || return 0
  ready[$i]=1
  if [ $set_ready -eq 1 ]; then
    check_set_ready_again "$i"
  else
    check_set_ready
  fi
}

# check_set_ready_again I: process I, respawned, is ready; when every process expected to run is
# ready too, the set is whole again.
check_set_ready_again() {
  local i j
  for j in "${!names[@]}"; do
    [ "${gone[$j]:-0}" -eq 1 ] || [ "${ready[$j]}" -eq 1 ] || return 0
  done
  echo "launch: set '$set_name' ready again (${names[$1]} respawned as pid ${pid_of[$1]})"
}

# ---- Liveliness: the watchers, their events, hung processes.
# start_watch GROUP: the watcher of this machine (-: every process of the set, the silent relay,
# lockstep drops) or of host GROUP (its processes only, inside its namespace).
start_watch() {
  local g=$1 i targets=() on_host=() extra=()
  for i in "${!names[@]}"; do
    [ "$g" = - ] || [ "${hosts[$i]}" = "$g" ] || continue
    if [ "${hang_afters[$i]}" = "$hang_after" ]; then targets+=("${names[$i]}"); else targets+=("${names[$i]}=${hang_afters[$i]}"); fi
  done
  if [ "$g" != - ]; then
    on_host=(ip netns exec "$hosts_net-$g" env AUTONOMY_HOST="$g" AUTONOMY_DDS_INTERFACE=hnet0)
    extra=(--no-relay --no-lockstep)
  fi
  CYCLONEDDS_URI=$(with_identity operator) setpriv --pdeathsig TERM "${on_host[@]}" "$bin/autonomy" node watch --domain "$domain" --hang-after "$hang_after" "${extra[@]}" "${targets[@]}" \
    >>"${watch_file_of[$g]}" 2>&1 </dev/null &
  watch_pid_of[$g]=$!
  watch_group_of_pid[$!]=$g
}

start_tick() { sleep 0.25 & tick=$!; }

# read_watch: handles the events each watcher appended to its file since the last call.
read_watch() {
  local line g
  for g in "${watch_groups[@]}"; do
    while IFS= read -r -u "${watch_fd_of[$g]}" line; do
      handle_watch_event "$g" "${watch_rest_of[$g]}$line"
      watch_rest_of[$g]=""
    done
    watch_rest_of[$g]+=$line
  done
}

# handle_watch_event GROUP LINE: "EVENT NAME pid PID on HOST: DETAIL" from the watcher of GROUP,
# about one of the set's processes as it runs now (events about an earlier pid are history), or
# "lockstep_dropped|lockstep_rejoined PARTICIPANT at tick T: REASON" from this machine's watcher.
handle_watch_event() {
  local g=$1 event name pid host detail i
  read -r event name _ pid _ host detail <<<"$2" || true
  case $event in
    lockstep_dropped) echo "launch: the simulator dropped $name from lockstep${2#lockstep_dropped $name}"; return 0 ;;
    lockstep_rejoined) echo "launch: $name is back in lockstep${2#lockstep_rejoined $name}"; return 0 ;;
  esac
  host=${host%:}
  [ -n "$name" ] && [ -n "$pid" ] || return 0
  i=${index_of_name[$name]:-}
  [ -n "$i" ] && [ "$host" = "${hosts[$i]:-$this_host}" ] && [ "$pid" = "${pid_of[$i]:-}" ] || return 0
  [ -n "${index_of_pid[$pid]:-}" ] || return 0
  if [ "$g" != "${hosts[$i]:--}" ]; then
    # This machine's watcher about a process of another host: what this machine hears, for the
    # record; its host's watcher decides.
    case $event in
      silent) echo "launch: $name (pid $pid) on $host is not heard on this machine: $detail; its host's watcher supervises it" ;;
      heard_again) echo "launch: $name (pid $pid) on $host is $detail on this machine" ;;
      hung) echo "launch: $name (pid $pid) on $host has not been heard on this machine for its hang limit (${detail#hung: }); its host's watcher hears it, so it is not hung: left running" ;;
    esac
    return 0
  fi
  case $event in
    heard) watched[$i]=1; became_ready "$i" ;;
    silent)
      local limit="hung after ${hang_afters[$i]} s"
      [ "$(awk -v s="${hang_afters[$i]}" 'BEGIN { print (s > 0) }')" = 1 ] || limit="never called hung: hang-after=0"
      echo "launch: $name (pid $pid) is silent: $detail; $limit" ;;
    heard_again) echo "launch: $name (pid $pid) is $detail; left running" ;;
    hung) process_hung "$i" "$pid" "$detail" ;;
  esac
}

# process_hung I PID DETAIL: report, then the process's on-exit policy.
process_hung() {
  local i=$1 pid=$2 name=${names[$1]}
  echo "launch: $name (pid $pid) is hung: ${3#hung: }"
  print_tail "${files[$i]}"
  case ${policies[$i]} in
    ignore)
      echo "launch: $name: on-exit=ignore, left as it is" ;;
    stop)
      echo "launch: $name: on-exit=stop, killing it (SIGKILL) and stopping the set"
      kill -KILL "$pid" 2>/dev/null || true
      stop_set; exit 1 ;;
    respawn)
      echo "launch: $name: on-exit=respawn, killing it (SIGKILL) to start it again"
      killed_hung[$i]=1
      kill -KILL "$pid" 2>/dev/null || true ;;
  esac
}

on_exit() { stop_set >/dev/null 2>&1 || true; }
trap on_exit EXIT
trap 'stop_request=SIGINT' INT
trap 'stop_request=SIGTERM' TERM
trap 'stop_request=SIGHUP' HUP  # the terminal closed

for i in "${!names[@]}"; do
  [ -z "${hosts[$i]}" ] || [[ " ${watch_groups[*]} " == *" ${hosts[$i]} "* ]] || watch_groups+=("${hosts[$i]}")
done
for g in "${watch_groups[@]}"; do
  watch_file_of[$g]=$run_dir/launch.watch
  [ "$g" = - ] || watch_file_of[$g]=$run_dir/launch.watch.$g
  : >"${watch_file_of[$g]}"
  exec {fd}<"${watch_file_of[$g]}"
  watch_fd_of[$g]=$fd watch_rest_of[$g]=""
  start_watch "$g"
done
for i in "${!names[@]}"; do start_process "$i"; done
start_tick

# One event loop: whichever child ends first (a set process, a readiness check, a back-off
# timer) is handled; a signal interrupts the wait at once.
while :; do
  if [ -n "$stop_request" ]; then
    echo "launch: $stop_request: stopping the set"
    stop_set; exit 0
  fi
  who="" status=0
  wait -n -p who 2>/dev/null || status=$?
  [ -z "$stop_request" ] || continue
  if [ -z "$who" ]; then
    # No child left: every process ended under on-exit=ignore.
    [ "$status" -eq 127 ] || continue
    echo "launch: no process of the set is left"
    stop_set; exit 0
  fi
  if [ "$who" = "$tick" ]; then
    read_watch
    start_tick
  elif [ -n "${index_of_pid[$who]:-}" ]; then
    i=${index_of_pid[$who]}; unset "index_of_pid[$who]"
    process_ended "$i" "$status" "$who"
    if [ ${#index_of_pid[@]} -eq 0 ] && [ ${#respawn_timer[@]} -eq 0 ]; then
      echo "launch: no process of the set is left"
      stop_set; exit 0
    fi
  elif [ -n "${watch_group_of_pid[$who]:-}" ]; then
    g=${watch_group_of_pid[$who]}; unset "watch_group_of_pid[$who]"
    read_watch
    of_host=""; [ "$g" = - ] || of_host=" of host $g"
    echo "launch: the liveliness watcher$of_host (autonomy node watch, pid $who) ended: $(describe_exit "$status"); starting it again in 1 s"
    tail -n 3 "${watch_file_of[$g]}" | sed 's/^/  | /'
    sleep 1 &
    watch_restart_of_pid[$!]=$g
  elif [ -n "${watch_restart_of_pid[$who]:-}" ]; then
    g=${watch_restart_of_pid[$who]}; unset "watch_restart_of_pid[$who]"
    start_watch "$g"
  elif [ -n "${respawn_timer[$who]:-}" ]; then
    i=${respawn_timer[$who]}; unset "respawn_timer[$who]"
    start_process "$i" respawn
  elif [ -n "${ready_check[$who]:-}" ]; then
    i=${ready_check[$who]}; unset "ready_check[$who]"
    ready_checked "$i" "$status"
  fi
done
