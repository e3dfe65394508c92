#!/usr/bin/env bash
# Configures and builds the tree into build/ (or build-asan/ with --sanitize): everything, or only
# the named targets and what they need. --demo builds the demo's programs only (the simulator, the
# behavior controller, the autonomy CLI and the viewer; no tests or benchmarks) in the same configuration, so
# a later full build reuses what it compiled.
# Usage: deploy/build.sh [--sanitize] [--release] [--demo] [--target NAME]...
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=build
args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
targets=()
while [ $# -gt 0 ]; do
  case $1 in
    # Benchmarks are not built with the sanitizers: their figures would mean nothing, and CI's
    # sanitizer build is the longer one.
    --sanitize) dir=build-asan; args=(-DCMAKE_BUILD_TYPE=Debug -DAUTONOMY_SANITIZE=ON -DAUTONOMY_BUILD_BENCH=OFF) ;;
    --release) args=(-DCMAKE_BUILD_TYPE=Release) ;;
    --demo) targets+=(simulator behavior autonomy viewer) ;;
    --target)
      [ $# -ge 2 ] || { echo "build: --target needs a target name" >&2; exit 2; }
      targets+=("$2"); shift ;;
    *) echo "build: unknown option $1 (use --sanitize, --release, --demo or --target NAME)" >&2; exit 2 ;;
  esac
  shift
done
cmake -S "$repo" -B "$repo/$dir" -G Ninja "${args[@]}" >/dev/null
if [ ${#targets[@]} -gt 0 ]; then
  cmake --build "$repo/$dir" --parallel "$(nproc)" --target "${targets[@]}"
else
  cmake --build "$repo/$dir" --parallel "$(nproc)"
fi
