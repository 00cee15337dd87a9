#!/usr/bin/env bash
# Builds kiln and runs every test (CTest over Catch2).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" "$here/build"
cd "$here/build" && ctest --output-on-failure -j "$(nproc)" "$@"
