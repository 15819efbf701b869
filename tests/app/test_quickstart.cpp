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
#include "tests/test_support.h"

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

/// Runs `bash scripts/quickstart.sh what` with the stand-ins first on PATH; returns the log.
std::string RunQuickstart(const std::string& what) {
  const std::string dir = test::ScratchDir("quickstart_" + what);
  const std::string log = dir + "/calls.log", bin = dir + "/bin", build = dir + "/build";
  fs::create_directories(bin);
  fs::create_directories(build);
  StandIn(bin + "/cmake", log);
  StandIn(bin + "/ctest", log);
  StandIn(bin + "/dpkg-query", log, "echo 'install ok installed'\n");
  StandIn(build + "/prt", log);
  const auto r = test::RunCommand("PATH=" + Q(bin) + ":\"$PATH\" PRT_BUILD_DIR=" + Q(build) + " bash " +
                                  Q(test::SourceDir() + "/scripts/quickstart.sh") + " " + what);
  CAPTURE(r.err);
  CHECK(r.exit_code == 0);
  return ReadFile(log);
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("quick start: demo builds only the prt program, test builds everything") {
    const std::string demo = RunQuickstart("demo");
    CAPTURE(demo);
    CHECK(demo.find("--target prt\n") != std::string::npos);
    CHECK(demo.find("prt demo\n") != std::string::npos);
    CHECK(demo.find("ctest --test-dir") == std::string::npos);
    const std::string all = RunQuickstart("test");
    CAPTURE(all);
    CHECK(all.find("cmake --build") != std::string::npos);
    CHECK(all.find("--target") == std::string::npos);  // every target: the tests too
    CHECK(all.find("ctest --test-dir") != std::string::npos);
    CHECK(all.find("prt demo") == std::string::npos);
  }
}

}  // namespace prt
