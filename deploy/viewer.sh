#!/usr/bin/env bash
# The viewer in the demo scripts (docs/viewer.md): adds it to a service set and says where it is.
#   deploy/viewer.sh set SET RUN_DIR PORT   prints the set to launch: SET plus a viewer line
#                                           (RUN_DIR/SET-with-viewer.set), or SET itself when
#                                           PORT is empty or build/bin/viewer is not built
#   deploy/viewer.sh address RUN_DIR PORT   prints the page's address once the set is ready, or
#                                           why there is none (on stderr)
# The viewer line has on-exit=ignore: a port in use ends the viewer, not the demo.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

case ${1:-} in
  set)
    [ $# -eq 4 ] || { echo "viewer.sh: usage: viewer.sh set SET RUN_DIR PORT" >&2; exit 2; }
    set_name=$2 run_dir=$3 port=$4
    if [ -z "$port" ] || [ ! -x "$repo/build/bin/viewer" ]; then
      echo "$set_name"
      exit 0
    fi
    set_file="$repo/deploy/sets/$set_name.set"
    [ -f "$set_file" ] || set_file=$set_name
    [ -f "$set_file" ] || { echo "viewer.sh: no service set $set_name" >&2; exit 2; }
    mkdir -p "$run_dir"
    out="$run_dir/$(basename "$set_file" .set)-with-viewer.set"
    { cat "$set_file"; echo "viewer/main  on-exit=ignore viewer --port $port"; } >"$out"
    echo "$out"
    ;;
  address)
    [ $# -eq 3 ] || { echo "viewer.sh: usage: viewer.sh address RUN_DIR PORT" >&2; exit 2; }
    run_dir=$2 port=$3
    [ -n "$port" ] || exit 0
    address=$(grep -o 'http://[^ ]*' "$run_dir/viewer-main.out" 2>/dev/null | head -n 1 || true)
    if [ -n "$address" ]; then
      echo "live view: open $address in a browser (from another machine: ssh -L $port:127.0.0.1:$port $(hostname) first; docs/viewer.md)"
    elif [ -f "$run_dir/viewer-main.out" ]; then
      echo "the viewer did not start (port $port in use? pick another with --viewer-port): $run_dir/viewer-main.out" >&2
    else
      echo "no viewer (build it: deploy/build.sh --target viewer)" >&2
    fi
    ;;
  *) echo "viewer.sh: usage: viewer.sh set SET RUN_DIR PORT | address RUN_DIR PORT" >&2; exit 2 ;;
esac
