#!/usr/bin/env bash
# Installs the job-shop baseline of planner_bench: MiniZinc with the Gecode solver, from Debian
# 12 packages (minizinc 2.6; flatzinc is Gecode's FlatZinc front end, fzn-gecode, with the
# solver configuration `minizinc --solver gecode` finds). Benchmark-only: not part of
# deploy/install-deps.sh. Idempotent.
set -euo pipefail

packages=(minizinc flatzinc libgecode49 libgecodeflatzinc49)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-minizinc: installing ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
minizinc --version | head -1
minizinc --solvers | grep -i gecode || {
  echo "install-minizinc: minizinc does not list a Gecode solver" >&2
  exit 1
}
