#!/usr/bin/env bash
# Installs the Debian packages kiln needs (when missing), then configures and builds.
# Usage: [KILN_TARGET=name] scripts/setup.sh [BUILD_DIR] [extra cmake args...]
# KILN_TARGET builds that target alone (scripts/bake.sh: the kiln executable, not the tests).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"; shift || true
pkgs=(cmake g++ make libopenexr-dev libtbb-dev libcli11-dev catch2 nlohmann-json3-dev zlib1g-dev glslang-tools)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" -j "$(nproc)" ${KILN_TARGET:+--target "$KILN_TARGET"}
