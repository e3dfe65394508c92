#!/usr/bin/env bash
# Starts a named service set in the background, waits until every process reports ready through
# its heartbeat, and stops the whole set cleanly on request or on Ctrl-C.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

usage() {
  cat <<USAGE
Usage: deploy/launch.sh [options] SET        start service set SET (deploy/sets/SET.set)
       deploy/launch.sh stop RUN_DIR         stop a set started with --detach
       deploy/launch.sh --list               list the service sets

Every process of the set runs in the background with its log and pid file in one run folder.
The script waits until each one's heartbeat says ready (autonomy node wait), then:
  - by default stays in the foreground; Ctrl-C (or SIGTERM) stops the whole set, and so does
    any process of the set exiting on its own;
  - with --detach returns at once, printing the run folder to pass to 'stop'.
Stopping sends SIGINT to every process, waits up to 10 s, then SIGKILLs what is left: no
orphans either way.

Options:
  --domain N        DDS domain id (default: \$AUTONOMY_DOMAIN or 0)
  --profile P       Cyclone DDS profile: loopback (default), lan, or a path to an XML file.
                    With lan, AUTONOMY_PEERS="host1 host2" adds unicast peers.
  --run-dir DIR     run folder (default: runs/SET-<date>-<time> in the repository)
  --bin DIR         folder of the programs (default: build/bin in the repository)
  --timeout S       seconds to wait for readiness (default 20)
  --detach          start and return
  -h, --help        this text

A set file has one process per line: NAME (service/instance as its heartbeat reports it), then
the program and its arguments. Lines starting with # are comments. {run} in an argument stands
for the run folder, {repo} for the repository. launch.sh adds --domain and --log-dir RUN_DIR to each.
USAGE
}

list_sets() { for f in "$repo"/deploy/sets/*.set; do basename "$f" .set; done; }

# stop_set RUN_DIR: SIGINT to every process of the run, SIGKILL after 10 s.
stop_set() {
  local run_dir=$1 pid name deadline alive
  shopt -s nullglob
  local pidfiles=("$run_dir"/*.pid)
  [ ${#pidfiles[@]} -gt 0 ] || { echo "launch: no pid files in $run_dir" >&2; return 1; }
  for f in "${pidfiles[@]}"; do
    pid=$(cat "$f")
    kill -INT "$pid" 2>/dev/null || true
  done
  deadline=$((SECONDS + 10))
  while :; do
    alive=0
    for f in "${pidfiles[@]}"; do kill -0 "$(cat "$f")" 2>/dev/null && alive=1; done
    [ $alive -eq 0 ] && break
    if [ $SECONDS -ge $deadline ]; then
      for f in "${pidfiles[@]}"; do
        pid=$(cat "$f"); name=$(basename "$f" .pid)
        if kill -0 "$pid" 2>/dev/null; then
          echo "launch: $name (pid $pid) ignored SIGINT for 10 s: killing it" >&2
          kill -KILL "$pid" 2>/dev/null || true
        fi
      done
      break
    fi
    sleep 0.1
  done
  rm -f "${pidfiles[@]}"
  echo "launch: stopped the set in $run_dir"
}

domain=${AUTONOMY_DOMAIN:-0}
profile=loopback
run_dir=""
bin="$repo/build/bin"
timeout=20
detach=0
set_name=""

while [ $# -gt 0 ]; do
  case $1 in
    -h|--help) usage; exit 0 ;;
    --list) list_sets; exit 0 ;;
    --domain) domain=$2; shift 2 ;;
    --profile) profile=$2; shift 2 ;;
    --run-dir) run_dir=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --timeout) timeout=$2; shift 2 ;;
    --detach) detach=1; shift ;;
    stop)
      [ $# -ge 2 ] || { echo "launch: stop needs the run folder" >&2; exit 2; }
      stop_set "$2"; exit $? ;;
    -*) echo "launch: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) [ -z "$set_name" ] || { echo "launch: one set at a time ($set_name, $1)" >&2; exit 2; }
       set_name=$1; shift ;;
  esac
done

[ -n "$set_name" ] || { usage >&2; exit 2; }
set_file="$repo/deploy/sets/$set_name.set"
[ -f "$set_file" ] || { echo "launch: no service set '$set_name'; known sets: $(list_sets | tr '\n' ' ')" >&2; exit 2; }
[[ "$domain" =~ ^[0-9]+$ ]] && [ "$domain" -le 232 ] || { echo "launch: --domain must be 0..232, got '$domain'" >&2; exit 2; }
[ -x "$bin/autonomy" ] || { echo "launch: $bin/autonomy not found: build first (cmake --build build)" >&2; exit 2; }

case $profile in
  loopback|lan) uri="file://$repo/deploy/dds/$profile.xml" ;;
  *) [ -f "$profile" ] || { echo "launch: profile file $profile not found" >&2; exit 2; }
     uri="file://$(cd "$(dirname "$profile")" && pwd)/$(basename "$profile")" ;;
esac
if [ "$profile" = lan ] && [ -n "${AUTONOMY_PEERS:-}" ]; then
  peers=""
  for p in $AUTONOMY_PEERS; do peers+="<Peer address=\"$p\"/>"; done
  uri+=",<Discovery><Peers>$peers</Peers></Discovery>"
fi
export CYCLONEDDS_URI=$uri
export AUTONOMY_DOMAIN=$domain

[ -n "$run_dir" ] || run_dir="$repo/runs/$set_name-$(date +%Y%m%d-%H%M%S)"
mkdir -p "$run_dir"
run_dir=$(cd "$run_dir" && pwd)

names=()
line_no=0
while IFS= read -r line || [ -n "$line" ]; do
  line_no=$((line_no + 1))
  line=${line%%#*}
  read -r -a words <<<"$line" || true
  [ ${#words[@]} -gt 0 ] || continue
  [ ${#words[@]} -ge 2 ] || { echo "launch: $set_file:$line_no: expected NAME PROGRAM [ARGS...]" >&2; stop_set "$run_dir" >/dev/null 2>&1 || true; exit 2; }
  name=${words[0]}; program=${words[1]}
  [ -x "$bin/$program" ] || { echo "launch: $set_file:$line_no: program $bin/$program not found" >&2; stop_set "$run_dir" >/dev/null 2>&1 || true; exit 2; }
  file_name=${name//\//-}
  args=()
  for w in "${words[@]:2}"; do w="${w//\{run\}/$run_dir}"; args+=("${w//\{repo\}/$repo}"); done
  # setsid: the processes do not share the terminal's process group, so only this script decides
  # how they are stopped (one SIGINT each), also when it runs detached.
  setsid "$bin/$program" "${args[@]}" --domain "$domain" --log-dir "$run_dir" \
    >"$run_dir/$file_name.out" 2>&1 </dev/null &
  echo $! >"$run_dir/$file_name.pid"
  names+=("$name")
  echo "launch: started $name (pid $!): $program ${args[*]}"
done <"$set_file"

cleanup() { trap - INT TERM EXIT; stop_set "$run_dir"; }
trap 'echo; cleanup; exit 0' INT TERM
[ $detach -eq 1 ] || trap cleanup EXIT

if ! "$bin/autonomy" node wait --domain "$domain" --timeout "$timeout" "${names[@]}"; then
  echo "launch: not every process became ready within $timeout s; last lines of their output:" >&2
  for n in "${names[@]}"; do
    echo "--- $n" >&2; tail -n 5 "$run_dir/${n//\//-}.out" >&2 || true
  done
  cleanup
  exit 1
fi
echo "launch: set '$set_name' ready on domain $domain; logs in $run_dir"

if [ $detach -eq 1 ]; then
  trap - INT TERM EXIT
  echo "launch: stop it with: deploy/launch.sh stop $run_dir"
  exit 0
fi

echo "launch: Ctrl-C stops the set"
while :; do
  for n in "${names[@]}"; do
    f="$run_dir/${n//\//-}.pid"
    if [ -f "$f" ] && ! kill -0 "$(cat "$f")" 2>/dev/null; then
      wait "$(cat "$f")" 2>/dev/null && code=0 || code=$?
      echo "launch: $n exited on its own (exit code $code); stopping the set" >&2
      rm -f "$f"
      cleanup
      exit 1
    fi
  done
  sleep 0.5
done
