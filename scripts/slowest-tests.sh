#!/usr/bin/env bash
# The slowest test cases of the last CTest run in a build folder, with their seconds, then each
# tier's seconds in that run against its budget:
#   bash scripts/slowest-tests.sh [BUILD_DIR] [COUNT]     (default build, 10)
# Reads BUILD_DIR/Testing/Temporary/LastTest.log, which every `ctest --test-dir BUILD_DIR` run
# writes, and the tier of each test from the labels the build folder registered (its
# prt_*_cases.cmake). The budgets are the table of tests/README.md ("Budgets"; PRT_BUDGET_TABLE
# names another file, for the tests of this script), in the column of
# the build folder's pass (Release, ASan + UBSan or TSan, from its CMakeCache.txt): seconds of
# test time, each test's own seconds summed, as CTest's "sec*proc". A tier over its budget is
# marked OVER: the change that put it there shows in its own run. The quick start's test command,
# scripts/sanitize.sh and so .ci/run print this after each suite.
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

# The pass of the build folder: its column of the budget table.
pass=Release
if grep -q '^PRT_SANITIZE:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then pass="ASan + UBSan"; fi
if grep -q '^PRT_TSAN:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then pass="TSan"; fi

# name<TAB>tier for every registered test: the tier is the label after the suite (unit, threads,
# e2e, readme).
tiers=$( (cat "$build"/prt_*_cases.cmake 2>/dev/null || true) | awk '
  /^set_tests_properties\(\[==\[/ {
    name = $0; sub(/^set_tests_properties\(\[==\[/, "", name); sub(/\]==\] PROPERTIES .*/, "", name)
    labels = $0; sub(/.* LABELS \[==\[/, "", labels); sub(/\]==\].*/, "", labels)
    n = split(labels, l, ";"); printf "%s\t%s\n", name, l[2]
  }')
awk -F '\t' -v pass="$pass" -v budgets="${PRT_BUDGET_TABLE:-tests/README.md}" '
  # The budget table: rows "| TIER | PROGRAM | Release | ASan + UBSan | TSan |" after "### Budgets".
  BEGIN {
    column["Release"] = 4; column["ASan + UBSan"] = 5; column["TSan"] = 6
    while ((getline line < budgets) > 0) {
      if (line ~ /^### Budgets/) { inside = 1; continue }
      if (inside && line ~ /^#/) inside = 0
      if (!inside || line !~ /^\| `?[a-z0-9]+`? \|/) continue
      split(line, cell, "|")
      tier = cell[2]; gsub(/[ `]/, "", tier)
      value = cell[column[pass]]; gsub(/[^0-9]/, "", value)
      if (value != "") budget[tier] = value + 0
      order[++tiers] = tier
    }
  }
  FNR == NR { tier_of[$1] = $2; next }
  {
    seconds = $1 + 0; name = $0; sub(/^ *[0-9.]+ s  /, "", name)
    t = (name in tier_of) ? tier_of[name] : "?"
    spent[t] += seconds; cases[t]++
  }
  END {
    printf "\nTiers of this run (%s pass; budgets: tests/README.md, \"Budgets\"):\n", pass
    printf "  %-8s %6s %10s %10s\n", "tier", "tests", "seconds", "budget"
    for (i = 1; i <= tiers; i++) {
      t = order[i]
      if (!(t in cases)) continue
      b = (t in budget) ? budget[t] : -1
      printf "  %-8s %6d %10.0f %10s%s\n", t, cases[t], spent[t], (b < 0 ? "none" : b), \
        (b >= 0 && spent[t] > b ? "  OVER" : (b < 0 ? "  (no budget for this pass)" : ""))
      shown[t] = 1
    }
    for (t in cases) if (!(t in shown)) printf "  %-8s %6d %10.0f %10s  (not a tier of the table)\n", t, cases[t], spent[t], "none"
  }
' <(printf '%s\n' "$tiers") <(printf '%s\n' "$times")
