#!/usr/bin/env bash
# The README's two commands:
#   bash scripts/quickstart.sh demo   installs what is missing, builds, runs `prt demo`
#   bash scripts/quickstart.sh test   installs what is missing, builds, runs every test: the
#                                     default suite, then the README's commands (the readme
#                                     tier), then prt farm on a real one-node Slurm (the slurm
#                                     tier), each followed by its slowest tests and its tiers'
#                                     seconds against their budgets (scripts/slowest-tests.sh);
#                                     last, how many were skipped and why (skipped-tests.sh)
# Each step is timed as a phase of .ci/run's table when PRT_PHASE_LOG is set (scripts/phase.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/phase.sh
source scripts/configure.sh
what=${1:-demo}
build=${PRT_BUILD_DIR:-build}
case "$what" in
  demo|test) ;;
  *) echo "usage: bash scripts/quickstart.sh demo|test" >&2; exit 2 ;;
esac

phase "install packages" bash scripts/install-deps.sh "$what"
configure "$build" -DCMAKE_BUILD_TYPE=Release

# Only what the command runs: the demo needs the program, the tests need everything.
case "$what" in
  demo) cmake --build "$build" --parallel "$(nproc)" --target prt
        "$build/prt" demo ;;
  test) phase "build (Release)" cmake --build "$build" --parallel "$(nproc)"
        bash scripts/slowest-files.sh "$build"
        # Two runs (tests/README.md, "Tiers"): the default suite (the unit, threads and e2e tiers),
        # then the README's commands as written (the readme tier), each followed by its slowest
        # tests and its tiers' seconds against their budgets.
        suite_log="$build/suite.log"
        status=0
        phase "suite (Release)" ctest --test-dir "$build" --output-on-failure --no-tests=error --parallel "$(nproc)" \
          --label-exclude '^(readme|slurm)$' | tee "$suite_log" || status=$?
        if [ -f "$build/Testing/Temporary/LastTest.log" ]; then bash scripts/slowest-tests.sh "$build"; fi
        phase "readme (Release)" ctest --test-dir "$build" --output-on-failure --no-tests=error --parallel "$(nproc)" \
          --label-regex '^readme$' | tee -a "$suite_log" || status=$?
        if [ -f "$build/Testing/Temporary/LastTest.log" ]; then bash scripts/slowest-tests.sh "$build" 5; fi
        # prt farm against a real Slurm of one node, which its test starts and stops (the slurm tier).
        phase "slurm (Release)" ctest --test-dir "$build" --output-on-failure --no-tests=error --parallel 1 \
          --label-regex '^slurm$' | tee -a "$suite_log" || status=$?
        if [ -f "$build/Testing/Temporary/LastTest.log" ]; then bash scripts/slowest-tests.sh "$build" 5; fi
        # The last line: how many tests were skipped, and for want of what (CTest's "100% tests
        # passed" counts a skipped test as neither passed nor failed).
        bash scripts/skipped-tests.sh "$suite_log"
        exit $status ;;
esac
