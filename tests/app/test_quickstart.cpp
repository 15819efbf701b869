// The README's quick start (scripts/quickstart.sh) builds only what its command runs: `demo` the
// prt program alone (the test program takes most of a fresh build), `test` everything. Checked
// with stand-ins for cmake, ctest and the built prt that record how they were called, so nothing
// is built here, and for dpkg-query, which answers that every package is installed (so
// scripts/install-deps.sh installs nothing).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;
using test::Q;

/// Writes an executable shell script `path` that appends "NAME ARGS" to `log`, then runs `tail`.
void StandIn(const std::string& path, const std::string& log, const std::string& tail = "") {
  std::ofstream(path) << "#!/bin/sh\necho \"" << fs::path(path).filename().string() << " $*\" >> " << Q(log) << "\n"
                      << tail;
  fs::permissions(path, fs::perms::owner_all);
}

/// What the ctest stand-in leaves as the run's log: three cases, the slowest in the middle.
constexpr const char* kCtestLog =
    "1/3 Test: fast one\nTest time =   0.25 sec\n"
    "2/3 Test: slow one\nTest time =  12.50 sec\n"
    "3/3 Test: middle one\nTest time =   3.00 sec\n";

/// Runs `bash scripts/quickstart.sh what` with the stand-ins first on PATH; returns the log, and
/// what the script printed in `out`.
std::string RunQuickstart(const std::string& what, std::string* out = nullptr) {
  const std::string dir = test::ScratchDir("quickstart_" + what);
  const std::string log = dir + "/calls.log", bin = dir + "/bin", build = dir + "/build";
  fs::create_directories(bin);
  fs::create_directories(build);
  StandIn(bin + "/cmake", log);
  StandIn(bin + "/ctest", log,
          "mkdir -p " + Q(build + "/Testing/Temporary") + " && printf '" + kCtestLog + "' > " +
              Q(build + "/Testing/Temporary/LastTest.log") + "\n");
  StandIn(bin + "/dpkg-query", log, "echo 'install ok installed'\n");
  StandIn(build + "/prt", log);
  // What the build registered: each case's suite and tier (tests/discover_tests.cmake).
  std::ofstream(build + "/prt_unit_tests_cases.cmake")
      << "set_tests_properties([==[fast one]==] PROPERTIES WORKING_DIRECTORY [==[x]==] LABELS [==[core;unit]==] TIMEOUT 600)\n";
  std::ofstream(build + "/prt_e2e_tests_cases.cmake")
      << "set_tests_properties([==[slow one]==] PROPERTIES WORKING_DIRECTORY [==[x]==] LABELS [==[app;e2e]==] TIMEOUT 600)\n"
      << "set_tests_properties([==[middle one]==] PROPERTIES WORKING_DIRECTORY [==[x]==] LABELS [==[view;e2e]==] TIMEOUT 600)\n";
  // A budget table of the test's own (tests/README.md's is the real one): e2e's 10 s is less
  // than the 15.5 its two cases take.
  std::ofstream(dir + "/budgets.md") << "## Tiers\n\n### Budgets\n\n| tier | program | Release | ASan + UBSan | TSan |\n"
                                        "|---|---|---|---|---|\n| `unit` | prt_unit_tests | 5 | 50 | - |\n"
                                        "| `e2e` | prt_e2e_tests | 10 | 20 | 5 |\n\n### Next\n\n| `e2e` | x | 99 | 99 | 99 |\n";
  // PRT_PHASE_LOG emptied: under .ci/run these steps are not CI's phases.
  const auto r = test::RunCommand("PATH=" + Q(bin) + ":\"$PATH\" PRT_PHASE_LOG= PRT_BUDGET_TABLE=" + Q(dir + "/budgets.md") +
                                  " PRT_BUILD_DIR=" + Q(build) + " bash " +
                                  Q(test::SourceDir() + "/scripts/quickstart.sh") + " " + what);
  CAPTURE(r.err);
  CHECK(r.exit_code == 0);
  if (out) *out = r.out;
  return ReadFile(log);
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("quick start: demo builds only the prt program, test builds everything, runs the default suite, the readme tier, then the slurm tier, and names the slowest tests and each tier's seconds") {
    const std::string demo = RunQuickstart("demo");
    CAPTURE(demo);
    CHECK(demo.find("--target prt\n") != std::string::npos);
    CHECK(demo.find("prt demo\n") != std::string::npos);
    CHECK(demo.find("ctest --test-dir") == std::string::npos);
    std::string printed;
    const std::string all = RunQuickstart("test", &printed);
    CAPTURE(all);
    CAPTURE(printed);
    // After the suite, its slowest cases, slowest first (scripts/slowest-tests.sh).
    const auto slow = printed.find("12.50 s  slow one"), middle = printed.find("3.00 s  middle one"),
               fast = printed.find("0.25 s  fast one");
    CHECK(printed.find("The slowest 10 of 3 test cases") != std::string::npos);
    CHECK(slow != std::string::npos);
    CHECK(middle != std::string::npos);
    CHECK(fast != std::string::npos);
    CHECK(slow < middle);
    CHECK(middle < fast);
    CHECK(all.find("cmake --build") != std::string::npos);
    CHECK(all.find(" -G Ninja ") != std::string::npos);  // a new build folder: Ninja
    CHECK(all.find("--target") == std::string::npos);  // every target: the tests too
    // The default suite, then the README's commands, then the slurm tier: three runs of ctest.
    const auto suite = all.find("--label-exclude ^(readme|slurm)$"), readme = all.find("--label-regex ^readme$"),
               slurm = all.find("--label-regex ^slurm$");
    CHECK(suite != std::string::npos);
    CHECK(readme != std::string::npos);
    CHECK(suite < readme);
    CHECK(readme < slurm);
    CHECK(slurm != std::string::npos);
    CHECK(all.find("prt demo") == std::string::npos);
    // Each tier's seconds in the run, against its Release budget of tests/README.md.
    const auto table = printed.find("Tiers of this run (Release pass");
    REQUIRE(table != std::string::npos);
    const std::string tiers = printed.substr(table, printed.find("\n\n", table) - table);
    CAPTURE(tiers);
    CHECK(tiers.find("\n  unit          1          0          5\n") != std::string::npos);
    CHECK(tiers.find("\n  e2e           2         16         10  OVER") != std::string::npos);  // 12.5 + 3 > 10
    CHECK(tiers.find("readme") == std::string::npos);  // no test of it ran
  }
}

}  // namespace prt
