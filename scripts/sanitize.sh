#!/usr/bin/env bash
# The test suite under the sanitizers:
#   bash scripts/sanitize.sh asan [doctest args]   AddressSanitizer + UndefinedBehaviorSanitizer
#                                                   (build-asan/), every test by default but the
#                                                   README suite: it reruns through the shell what
#                                                   other tests run in-process, and took 122 s of
#                                                   the 193 s unsanitized suite (2 vCPUs). By
#                                                   default through ctest, one process per core
#   bash scripts/sanitize.sh tsan [doctest args]   ThreadSanitizer (build-tsan/), the threaded
#                                                   stages by default: core (thread pool),
#                                                   precompute (transport), video (frames from
#                                                   several threads) and app (rendering), through
#                                                   ctest likewise
#   bash scripts/sanitize.sh all                    both, one after the other
# The `prt` binary that the command-line tests run is the sanitized one too. Any report fails
# the run (halt_on_error). PRT_JOBS sets the build parallelism (default: all cores).
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-asan}
shift || true
jobs=${PRT_JOBS:-$(nproc)}

build() {  # build FOLDER CMAKE_OPTION
  cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-D$2=ON" >/dev/null
  cmake --build "$1" --parallel "$jobs" --target prt prt_tests
}

# Without doctest arguments the default tests run through CTest, one test case per process and
# one process per core (the suites ran serially on one core before, which made them most of CI's
# time); with arguments, prt_tests runs them itself, as before.
run_suite() {  # run_suite NAME FOLDER "DEFAULT TESTS" "CTEST SELECTION" [DOCTEST ARGS...]
  local name=$1 folder=$2 what=$3 selection=$4
  shift 4
  if [ $# -eq 0 ]; then
    echo "== $name: $what, through ctest"
    ctest --test-dir "$folder" --output-on-failure --no-tests=error --parallel "$jobs" $selection
  else
    echo "== $name: prt_tests $*"
    "$folder/prt_tests" --no-intro=true "$@"
  fi
}

run_asan() {
  build build-asan PRT_SANITIZE
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  run_suite "AddressSanitizer + UndefinedBehaviorSanitizer" build-asan "every test but the readme suite" \
    "--label-exclude ^readme$" "$@"
}

run_tsan() {
  build build-tsan PRT_TSAN
  export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
  run_suite "ThreadSanitizer" build-tsan "the core, precompute, video and app suites" \
    "--label-regex ^(core|precompute|video|app)$" "$@"
}

case "$what" in
  asan) run_asan "$@" ;;
  tsan) run_tsan "$@" ;;
  all) run_asan && run_tsan ;;
  *) echo "usage: bash scripts/sanitize.sh asan|tsan|all [doctest args]" >&2; exit 2 ;;
esac
