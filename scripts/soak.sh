#!/usr/bin/env bash
# The suite under load: runs scripts/test.sh N times in a row (default 20) in this checkout while a
# fresh clone of HEAD in a temporary folder runs scripts/test.sh again and again beside it (issue
# #17: a test that depends on timing or scheduling must show here). Prints one line per run and
# exits non-zero if any run of either side failed; the logs stay in the printed folder.
# Usage: scripts/soak.sh [N]
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
runs="${1:-20}"
work="$(mktemp -d /tmp/kiln-soak.XXXXXX)"
git clone -q "$here" "$work/beside"
"$work/beside/scripts/setup.sh" "$work/beside/build" > "$work/beside-setup.log" 2>&1 ||
  { echo "soak: the clone beside does not build (see $work/beside-setup.log)"; exit 1; }
(
  i=0
  while [ ! -e "$work/stop" ]; do
    i=$((i + 1))
    "$work/beside/scripts/test.sh" > "$work/beside.$i.log" 2>&1
    echo "beside $i rc=$?" >> "$work/beside.rc"
  done
) &
failed=0
for i in $(seq 1 "$runs"); do
  start=$(date +%s)
  "$here/scripts/test.sh" > "$work/run.$i.log" 2>&1
  rc=$?
  [ "$rc" -eq 0 ] || failed=1
  echo "run $i/$runs rc=$rc $(( $(date +%s) - start )) s, load $(cut -d' ' -f1 /proc/loadavg)"
done
touch "$work/stop"
wait
grep -q -v "rc=0" "$work/beside.rc" && failed=1
echo "beside: $(grep -c "rc=0" "$work/beside.rc") of $(wc -l < "$work/beside.rc") runs passed"
echo "logs: $work"
exit "$failed"
