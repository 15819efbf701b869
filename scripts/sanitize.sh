#!/usr/bin/env bash
# The test suite under the sanitizers, tier by tier (tests/README.md, "Tiers"):
#   bash scripts/sanitize.sh asan [ctest args]   AddressSanitizer + UndefinedBehaviorSanitizer
#                                                 (build-asan/): the unit and threads tiers, and
#                                                 the e2e tier's smoke set for asan
#   bash scripts/sanitize.sh tsan [ctest args]   ThreadSanitizer (build-tsan/): the threads tier,
#                                                 and the e2e tier's smoke set for tsan
#   bash scripts/sanitize.sh all                  both, one after the other
# Each sanitized build folder compiles prt and the programs of its tiers only (PRT_TEST_TIERS),
# with Ninja when the folder is new (configure.sh), and each build ends with what it cost
# (slowest-files.sh).
# The smoke set (tests/smoke.txt) is run by the e2e program of the Release build ($PRT_BUILD_DIR,
# default build/; built here first if it is missing) against the sanitized prt (tests/smoke.cmake):
# those tests only start prt and read what it writes. Arguments after the pass go to ctest (-R
# cache, -L threads). Every test case runs as its own process, one process per core; any report
# fails the run (halt_on_error). Each pass ends with its slowest tests and its tiers' seconds
# against their budgets (scripts/slowest-tests.sh). PRT_JOBS sets the build parallelism (default:
# all cores). Each build and suite is timed as a phase of .ci/run's table when PRT_PHASE_LOG is
# set (scripts/phase.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/phase.sh
source scripts/configure.sh
what=${1:-asan}
shift || true
jobs=${PRT_JOBS:-$(nproc)}
release=${PRT_BUILD_DIR:-build}
case "$release" in /*) release_path=$release ;; *) release_path=$PWD/$release ;; esac

# -O1 -g1: GCC compiles the sanitized objects in half the time of RelWithDebInfo's -O2 -g (the
# compiler's seconds over 21 of the files: 207 s at -O2 -g, 146 at -O2 -g1, 105 at -O1 -g1, 94 at
# -O1 without debug information; AMD EPYC, 2 vCPUs); -g1 keeps the file and line of every frame
# of a sanitizer's report, and -O1 is what the sanitizers' own documentation recommends.
# The functions below run as `run_asan && run_tsan`, where bash's `set -e` does not apply inside
# them: every step that can fail returns its status explicitly.
build() {  # build NAME FOLDER CMAKE_OPTION TIERS
  configure "$2" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
    "-D$3=ON" "-DPRT_TEST_TIERS=$4" "-DPRT_SMOKE_DRIVER=$release_path/prt_e2e_tests" || return
  phase "build ($1)" cmake --build "$2" --parallel "$jobs" || return
  bash scripts/slowest-files.sh "$2"
}

# The smoke set's program: the Release build's e2e tests (a no-op when CI's Release build has it).
smoke_driver() {
  if [ ! -f "$release/CMakeCache.txt" ]; then configure "$release" -DCMAKE_BUILD_TYPE=Release || return; fi
  cmake --build "$release" --parallel "$jobs" --target prt_e2e_tests >/dev/null
}

run_suite() {  # run_suite NAME FOLDER [CTEST ARGS...]
  local name=$1 folder=$2
  shift 2
  echo "== $name: the tiers of $folder, through ctest"
  local status=0
  phase "suite ($name)" ctest --test-dir "$folder" --output-on-failure --no-tests=error --parallel "$jobs" "$@" \
    || status=$?
  if [ -f "$folder/Testing/Temporary/LastTest.log" ]; then bash scripts/slowest-tests.sh "$folder"; fi
  return $status
}

run_asan() {
  smoke_driver || return
  build "ASan + UBSan" build-asan PRT_SANITIZE "unit;threads" || return
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  run_suite "ASan + UBSan" build-asan "$@"
}

# The modules with a stage that runs on several threads (a thread pool, worker or writer
# threads, a library's server threads, atomics, mutexes) each have tests in the threads tier,
# which is what ThreadSanitizer runs; a test (tests/app/test_ci_scripts.cpp) reads src/ and fails
# when a module with threaded code has none there and is not in TSAN_LEFT_OUT. Left out, each
# with its reason:
# - report: `prt report`'s studies, built on precompute's stages (under TSan through precompute's
#   threads tests); its own parallel loop, the stability suite's lowest value over 200,000
#   directions, is core's ParallelFor over disjoint chunks.
# - geometry: no thread of its own; the BVH is traversed from the transport's worker threads
#   (under TSan through precompute's threads tests), and its one atomic, the kernels' instruction
#   set, is chosen at start (tests and benchmarks switch it between runs, never during one).
TSAN_LEFT_OUT="report geometry"

run_tsan() {
  smoke_driver || return
  build "TSan" build-tsan PRT_TSAN "threads" || return
  # atexit_sleep_ms=0: by default ThreadSanitizer sleeps a second at the exit of every process
  # that still has a thread (prt's signal watcher), to catch races with threads still running;
  # that second was most of the suite (a test that runs prt 40 times took 43 s, 0.9 s without
  # it). prt joins its workers before it exits, and its tests check what they leave behind.
  # suppressions: the interceptors that Debian's uninstrumented cpp-httplib calls, for prt view
  # (scripts/tsan-suppressions.txt says why).
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:atexit_sleep_ms=0:suppressions=$PWD/scripts/tsan-suppressions.txt"
  run_suite "TSan" build-tsan "$@"
}

case "$what" in
  asan) run_asan "$@" ;;
  tsan) run_tsan "$@" ;;
  all) run_asan && run_tsan ;;
  *) echo "usage: bash scripts/sanitize.sh asan|tsan|all [ctest args]" >&2; exit 2 ;;
esac
