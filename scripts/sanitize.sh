#!/usr/bin/env bash
# The test suite under the sanitizers:
#   bash scripts/sanitize.sh asan [doctest args]   AddressSanitizer + UndefinedBehaviorSanitizer
#                                                   (build-asan/), every test but the README
#                                                   suite and the whole report studies
#                                                   (ASAN_LEFT_OUT below says why)
#   bash scripts/sanitize.sh tsan [doctest args]   ThreadSanitizer (build-tsan/), every test of a
#                                                   module with threaded code (THREADED below)
#   bash scripts/sanitize.sh all                    both, one after the other
# Without doctest arguments the tests run through CTest, one test case per process and one
# process per core; with arguments, prt_tests runs them itself. The `prt` binary that the
# command-line tests run is the sanitized one too. Any report fails the run (halt_on_error).
# Tests whose work is made smaller under a sanitizer are listed in tests/README.md.
# PRT_JOBS sets the build parallelism (default: all cores). Each build and suite is timed as a
# phase of .ci/run's table when PRT_PHASE_LOG is set (scripts/phase.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/phase.sh
what=${1:-asan}
shift || true
jobs=${PRT_JOBS:-$(nproc)}

# -O1 -g1: GCC compiles the sanitized objects in half the time of RelWithDebInfo's -O2 -g (the
# compiler's seconds over 21 of the files: 207 s at -O2 -g, 146 at -O2 -g1, 105 at -O1 -g1, 94 at
# -O1 without debug information; AMD EPYC, 2 vCPUs); -g1 keeps the file and line of every frame
# of a sanitizer's report, and -O1 is what the sanitizers' own documentation recommends.
# The functions below run as `run_asan && run_tsan`, where bash's `set -e` does not apply inside
# them: every step that can fail returns its status explicitly.
build() {  # build NAME FOLDER CMAKE_OPTION
  cmake -S . -B "$2" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
    "-D$3=ON" >/dev/null || return
  phase "build ($1)" cmake --build "$2" --parallel "$jobs" --target prt prt_tests
}

run_suite() {  # run_suite NAME FOLDER "DEFAULT TESTS" "CTEST SELECTION" [DOCTEST ARGS...]
  local name=$1 folder=$2 what=$3 selection=$4
  shift 4
  if [ $# -eq 0 ]; then
    echo "== $name: $what, through ctest"
    local status=0
    phase "suite ($name)" ctest --test-dir "$folder" --output-on-failure --no-tests=error --parallel "$jobs" \
      $selection || status=$?
    if [ -f "$folder/Testing/Temporary/LastTest.log" ]; then bash scripts/slowest-tests.sh "$folder"; fi
    return $status
  else
    echo "== $name: prt_tests $*"
    "$folder/prt_tests" --no-intro=true "$@"
  fi
}

# The labels whose tests do not run under AddressSanitizer + UndefinedBehaviorSanitizer, each with
# its reason (a test, tests/app/test_ci_scripts.cpp, holds the ctest call to this list):
# - readme: it reruns through the shell what other tests run in-process.
# - report_study: the tests that run a whole `prt report` study end to end (test::WholeStudy()):
#   loops over precompute's, the wavelets' and the glossy stages, which run under ASan through
#   their own tests, and over report's writers (under ASan through the report suite's own tests:
#   tables, plots, timing). Eight tests were 1199 s of a 2176 s ASan suite's test time (Intel
#   Xeon, 2 vCPUs), each already at a smaller size than unsanitized; the Release suite runs them.
ASAN_LEFT_OUT="readme report_study"

run_asan() {
  build "ASan + UBSan" build-asan PRT_SANITIZE || return
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  run_suite "ASan + UBSan" build-asan "every test but the labels ASAN_LEFT_OUT names" \
    "--label-exclude ^(${ASAN_LEFT_OUT// /|})$" "$@"
}

# The modules with a stage that runs on several threads (a thread pool, worker or writer
# threads, atomics, mutexes), each a test label. A test (tests/app/test_ci_scripts.cpp) reads
# src/ and fails when a module with threaded code is neither here nor in TSAN_LEFT_OUT.
THREADED="core|sh|env|material|wavelet|precompute|precompute_io|cpca|raster|render|video|view|app"
# Modules with threaded code whose tests do not run under ThreadSanitizer, each with its reason:
# - report: `prt report`'s studies, built on precompute's stages (under TSan through precompute's
#   and app's tests); its own parallel loop, the stability suite's lowest value over 200,000
#   directions, is core's ParallelFor over disjoint chunks. Its tests were 561 s of an 833 s
#   TSan suite (the glossy section alone 254 s, its lobe tables fixed whatever the mesh).
# - geometry: no thread of its own; the BVH is traversed from the transport's worker threads
#   (under TSan through precompute's tests), and its one atomic, the kernels' instruction set,
#   is chosen at start (tests and benchmarks switch it between runs, never during one).
TSAN_LEFT_OUT="report geometry"

run_tsan() {
  build "TSan" build-tsan PRT_TSAN || return
  # atexit_sleep_ms=0: by default ThreadSanitizer sleeps a second at the exit of every process
  # that still has a thread (prt's signal watcher), to catch races with threads still running;
  # that second was most of the suite (a test that runs prt 40 times took 43 s, 0.9 s without
  # it). prt joins its workers before it exits, and its tests check what they leave behind.
  # suppressions: the interceptors that Debian's uninstrumented cpp-httplib calls, for prt view
  # (scripts/tsan-suppressions.txt says why).
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:atexit_sleep_ms=0:suppressions=$PWD/scripts/tsan-suppressions.txt"
  run_suite "TSan" build-tsan "the modules with threaded code" "--label-regex ^($THREADED)$" "$@"
}

case "$what" in
  asan) run_asan "$@" ;;
  tsan) run_tsan "$@" ;;
  all) run_asan && run_tsan ;;
  *) echo "usage: bash scripts/sanitize.sh asan|tsan|all [doctest args]" >&2; exit 2 ;;
esac
