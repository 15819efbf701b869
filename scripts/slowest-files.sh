#!/usr/bin/env bash
# What a build folder's last build cost: the compiler's seconds per target, and the files that
# took longest to compile, from Ninja's log of each step's start and end:
#   bash scripts/slowest-files.sh [BUILD_DIR] [COUNT]     (default build, 10)
# The quick start's test command and scripts/sanitize.sh (so .ci/run) print it after each build.
# A step's seconds are its wall time, taken while the other cores compiled too. A folder built by
# another generator than Ninja has no such log: the script says so and succeeds.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
count=${2:-10}
log=$build/.ninja_log
if [ ! -f "$log" ]; then
  echo "slowest-files: $build was not built with Ninja (no .ninja_log): no compile times"
  exit 0
fi
# The log appends every build's steps: the last line of each output is its latest compile.
awk -F '\t' -v count="$count" -v build="$build" '
  /^#/ { next }
  { seconds[$4] = ($2 - $1) / 1000 }
  END {
    for (out in seconds) {
      if (out !~ /\.o$/) continue
      target = out
      if (match(out, /[A-Za-z0-9_]+\.dir\//)) target = substr(out, RSTART, RLENGTH - 5)
      per_target[target] += seconds[out]; total += seconds[out]; files++
      lines[files] = sprintf("%09.1f\t%s", seconds[out], out)
    }
    printf "The compiler in %s: %.0f s over %d files", build, total, files
    n = 0
    for (t in per_target) order[++n] = t
    # by seconds, largest first
    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (per_target[order[j]] > per_target[order[i]]) { x = order[i]; order[i] = order[j]; order[j] = x }
    sep = " ("
    for (i = 1; i <= n; i++) { printf "%s%s %.0f s", sep, order[i], per_target[order[i]]; sep = ", " }
    printf ")\n"
    m = 0
    for (k in lines) sorted[++m] = lines[k]
    for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (sorted[j] > sorted[i]) { x = sorted[i]; sorted[i] = sorted[j]; sorted[j] = x }
    printf "The %d slowest to compile:\n", (count < m ? count : m)
    for (i = 1; i <= count && i <= m; i++) {
      split(sorted[i], f, "\t"); name = f[2]; sub(/^.*\.dir\//, "", name); sub(/\.o$/, "", name)
      printf "%8.1f s  %s\n", f[1] + 0, name
    }
  }
' "$log"
