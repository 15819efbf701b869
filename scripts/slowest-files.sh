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
tab=$'\t'
# The log appends every build's steps: the last line of each output is its latest compile.
# One line per object file: seconds, target, source (slowest first).
files=$(awk -F '\t' '
  /^#/ { next }
  { seconds[$4] = ($2 - $1) / 1000 }
  END {
    for (out in seconds) {
      if (out !~ /\.o$/) continue
      target = out
      if (match(out, /[A-Za-z0-9_]+\.dir\//)) target = substr(out, RSTART, RLENGTH - 5)
      name = out; sub(/^.*\.dir\//, "", name); sub(/\.o$/, "", name)
      printf "%.3f\t%s\t%s\n", seconds[out], target, name
    }
  }' "$log" | sort -t "$tab" -k1,1gr -k3,3)
# The seconds per target, largest first, on the summary's line.
targets=$(awk -F '\t' 'NF { s[$2] += $1 } END { for (t in s) printf "%.3f\t%s\n", s[t], t }' <<<"$files" |
  sort -t "$tab" -k1,1gr -k2,2 | awk -F '\t' '{ printf "%s%s %.0f s", (NR > 1 ? ", " : ""), $2, $1 }')
awk -F '\t' -v build="$build" -v targets="$targets" 'NF { total += $1; n++ }
  END { printf "The compiler in %s: %.0f s over %d files%s\n", build, total, n, (n ? " (" targets ")" : "") }' <<<"$files"
shown=$(grep -c . <<<"$files" || true)
[ "$shown" -le "$count" ] || shown=$count
echo "The $shown slowest to compile:"
head -n "$count" <<<"$files" | awk -F '\t' 'NF { printf "%8.1f s  %s\n", $1, $3 }'
