#!/usr/bin/env bash
# bash scripts/skipped-tests.sh CTEST_OUTPUT
# One line: how many tests CTest's output (a run of the suite) reports as skipped, and what they
# lack. A test is skipped, never passed, when what it compares with is absent (tests/README.md):
# the course's files in ../shared/data (a user's clone does not have them), ffmpeg, cmark-gfm,
# chromium and python3 (which drives it), and the slurm tier's root with Slurm's daemons.
set -euo pipefail
cd "$(dirname "$0")/.."
skipped=$(grep -c '(Skipped)$' "$1" || true)
if [ "$skipped" -eq 0 ]; then
  echo "tests: none skipped"
  exit 0
fi
lacking=()
data=${PRT_SHARED_DATA:-../shared/data}
if [ "$data" = none ] || [ ! -d "$data" ]; then
  lacking+=("the course's files (../shared/data, beside the clone; a fresh clone does not have them)")
fi
command -v ffmpeg >/dev/null || lacking+=("ffmpeg")
command -v cmark-gfm >/dev/null || lacking+=("cmark-gfm")
command -v chromium >/dev/null || lacking+=("chromium")
command -v python3 >/dev/null || lacking+=("python3")
{ [ "$EUID" -eq 0 ] && command -v slurmctld >/dev/null && command -v slurmd >/dev/null && command -v munged >/dev/null &&
  command -v sbatch >/dev/null && command -v sinfo >/dev/null; } ||
  lacking+=("$([ "$EUID" -eq 0 ] || echo "root with ")Slurm (slurm-wlm, munge)")
reason="what they compare with"
if [ ${#lacking[@]} -gt 0 ]; then
  reason=$(printf '%s, ' "${lacking[@]}")
  reason=${reason%, }
fi
echo "tests: $skipped skipped, not passed, for want of $reason; tests/README.md says what each needs"
