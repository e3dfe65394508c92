#!/usr/bin/env bash
# Installs every build and run dependency from Debian 12 packages. Idempotent: packages already
# present are left alone, so running it twice costs one apt-get update at most.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # transport: Cyclone DDS C library, idlc, ddsperf
  cyclonedds-dev cyclonedds-tools
  # maths, path planning, logging, files
  libeigen3-dev libompl-dev libspdlog-dev libfmt-dev libprotobuf-dev protobuf-compiler
  # ROS map_server YAML files (occupancy maps)
  libyaml-cpp-dev
  # recordings: zstd compression of MCAP chunks (common/mcap)
  libzstd-dev
  # the courier's journal of accepted commands and jobs (embedded SQLite, WAL)
  libsqlite3-dev
  # OMPL's CMake variables name these boost libraries
  libboost-serialization-dev libboost-filesystem-dev libboost-system-dev
  # the viewer's web server and WebSocket (Boost.Beast, header-only)
  libboost-dev
  # arguments (CLI11) and JSON (nlohmann): well kept, header-only, replace hand-written parsers
  libcli11-dev nlohmann-json3-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # wire inspection (packet capture of the demo) and the demo script's JSON reading
  tshark procps iproute2 jq
  # DDS Security: certificate authorities, identities, signed permissions (deploy/security/security.sh)
  openssl
  # several hosts on one machine (deploy/hosts.sh): network namespaces, loss and partitions
  nftables
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
# tshark asks whether non-root users may capture; answer once, non-interactively.
echo "wireshark-common wireshark-common/install-setuid boolean false" | debconf-set-selections
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
