#!/usr/bin/env bash
# The README's two commands:
#   bash scripts/quickstart.sh demo   installs what is missing, builds, runs `prt demo`
#   bash scripts/quickstart.sh test   installs what is missing, builds, runs every test
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-demo}
build=${PRT_BUILD_DIR:-build}
case "$what" in
  demo|test) ;;
  *) echo "usage: bash scripts/quickstart.sh demo|test" >&2; exit 2 ;;
esac

bash scripts/install-deps.sh "$what"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null

# Only what the command runs: the demo needs the program, the tests need everything.
case "$what" in
  demo) cmake --build "$build" --parallel "$(nproc)" --target prt
        "$build/prt" demo ;;
  test) cmake --build "$build" --parallel "$(nproc)"
        ctest --test-dir "$build" --output-on-failure --no-tests=error --parallel "$(nproc)" ;;
esac
