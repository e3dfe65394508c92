#!/usr/bin/env bash
# Configures and builds the whole tree into build/ (or build-asan/ with --sanitize).
# Usage: deploy/build.sh [--sanitize] [--release]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=build
args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
for a in "$@"; do
  case $a in
    --sanitize) dir=build-asan; args=(-DCMAKE_BUILD_TYPE=Debug -DAUTONOMY_SANITIZE=ON) ;;
    --release) args=(-DCMAKE_BUILD_TYPE=Release) ;;
    *) echo "build: unknown option $a (use --sanitize or --release)" >&2; exit 2 ;;
  esac
done
cmake -S "$repo" -B "$repo/$dir" -G Ninja "${args[@]}" >/dev/null
cmake --build "$repo/$dir" --parallel "$(nproc)"
