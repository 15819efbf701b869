#!/usr/bin/env bash
# The slowest test cases of the last CTest run in a build folder, with their seconds:
#   bash scripts/slowest-tests.sh [BUILD_DIR] [COUNT]     (default build, 10)
# Reads BUILD_DIR/Testing/Temporary/LastTest.log, which every `ctest --test-dir BUILD_DIR` run
# writes; the quick start's test command and .ci/run print it after each suite.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
count=${2:-10}
log=$build/Testing/Temporary/LastTest.log
if [ ! -f "$log" ]; then
  echo "slowest-tests: $log is missing: run the tests first (ctest --test-dir $build)" >&2
  exit 2
fi
times=$(awk '
  /^[0-9]+\/[0-9]+ Test: / { sub(/^[0-9]+\/[0-9]+ Test: /, ""); name = $0; next }
  /^Test time = / && name != "" { printf "%9.2f s  %s\n", $4, name; name = "" }
' "$log" | sort -rn)
total=$(awk '{ s += $1 } END { printf "%.0f", s }' <<<"$times")
echo "The slowest $count of $(grep -c . <<<"$times") test cases in $build ($total s of test time in all):"
head -n "$count" <<<"$times"
