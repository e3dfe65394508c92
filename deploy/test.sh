#!/usr/bin/env bash
# Installs the dependencies, builds, and runs every test (unit and integration, with real DDS
# processes on loopback). --sanitize builds and tests the ASan + UBSan configuration instead;
# --all runs both configurations one after the other.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

configs=(plain)
case ${1:-} in
  "") ;;
  --sanitize) configs=(sanitize) ;;
  --all) configs=(plain sanitize) ;;
  *) echo "test: unknown option $1 (use --sanitize or --all)" >&2; exit 2 ;;
esac

bash "$repo/deploy/install-deps.sh"
# Test-only npm packages, pinned by tests/node/package-lock.json, never in the runtime install:
# the independent MCAP readers of the recording test (@mcap/core, @foxglove/omgidl-serialization)
# and the Foxglove WebSocket client of the viewer test (@foxglove/ws-protocol, ws). Without node
# those tests say so and skip that part.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends nodejs npm ||
    echo "test: nodejs/npm could not be installed; the checks by independent readers (MCAP, Foxglove) will be skipped" >&2
fi
if command -v npm >/dev/null 2>&1; then
  npm ci --prefix "$repo/tests/node" --no-audit --no-fund --loglevel=error
fi
# Test-only: Debian's chromium, headless, for the viewer's page check (tests/node/viewer_page_check.js;
# about 20 s to install here). Without it that test says so and skips.
if ! command -v chromium >/dev/null 2>&1; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium ||
    echo "test: chromium could not be installed; the viewer's browser check will be skipped" >&2
fi
for c in "${configs[@]}"; do
  if [ "$c" = sanitize ]; then
    echo "== ASan + UBSan build and tests"
    bash "$repo/deploy/build.sh" --sanitize
    dir="$repo/build-asan"
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    # Tests labelled plain_only (tests/CMakeLists.txt says why each one is) run in the plain build.
    only=(--label-exclude plain_only)
  else
    echo "== build and tests"
    bash "$repo/deploy/build.sh"
    dir="$repo/build"
    only=()
  fi
  # Two cores: two tests at a time. Integration tests use one DDS domain each, so they can overlap.
  ctest --test-dir "$dir" --parallel 2 --output-on-failure --timeout 300 "${only[@]}"
done
