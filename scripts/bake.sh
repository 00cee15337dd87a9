#!/usr/bin/env bash
# Builds kiln and bakes the default catalogue into luts/ (extra args go to `kiln bake`).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
KILN_TARGET=kiln "$here/scripts/setup.sh" "$here/build"
"$here/build/kiln" bake --out "$here/luts" "$@"
