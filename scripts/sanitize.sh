#!/usr/bin/env bash
# Builds kiln and every test with AddressSanitizer + UndefinedBehaviorSanitizer (the KILN_SANITIZE
# option of CMakeLists.txt) into build-asan/, then runs the tests with CTest (the [long] tests
# stay out, as in the normal run). Any sanitizer report fails the test that triggered it: the
# build uses -fno-sanitize-recover=all, and the CLI tests run the instrumented kiln binary too.
# Usage: scripts/sanitize.sh [ctest args...]     e.g. scripts/sanitize.sh -R stress
# Environment: KILN_ASAN_BUILD (build folder), KILN_JOBS (ctest -j, default: nproc).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KILN_ASAN_BUILD:-$here/build-asan}"
# RelWithDebInfo: -O2 as the release build, plus -g so that reports have file:line.
"$here/scripts/setup.sh" "$build" -DKILN_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cd "$build"
ctest --output-on-failure -j "${KILN_JOBS:-$(nproc)}" "$@"
