// The tiers of the tests themselves (tests/README.md, "Tiers"): every test file is in exactly one
// tier, and a sanitized build folder, configured as scripts/sanitize.sh configures it, registers
// its own tiers' programs and the smoke set of its pass (tests/smoke.txt, read here on its own),
// each smoke test run by another build's e2e program against the folder's own prt. CMake and
// CTest run for real (a configure and `ctest -N -V`); nothing is compiled.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <tuple>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;
using test::Q;

/// The names tests/smoke.txt gives `pass` ("asan: NAME" lines).
std::set<std::string> SmokeNames(const std::string& pass) {
  std::istringstream lines(ReadFile(test::SourceDir() + "/tests/smoke.txt"));
  std::set<std::string> names;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(pass + ": ", 0) == 0) names.insert(line.substr(pass.size() + 2));
  return names;
}

/// A registered test as `ctest -N -V` shows it: its labels and environment.
struct Registered {
  std::set<std::string> labels;
  std::vector<std::string> environment;
};

/// The tests a configured build folder registers, by name, from `ctest -N -V`: per test a block
/// of lines "K: Environment variables:" and "K:  NAME=VALUE", "Labels: A B", then "  Test #K: NAME"
/// (K padded with spaces to the widest number).
std::map<std::string, Registered> Registrations(const std::string& folder) {
  const test::RunResult r = test::RunCommand("ctest --test-dir " + Q(folder) + " -N -V");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  std::map<std::string, Registered> tests;
  Registered current;
  bool environment = false;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t colon = line.find(": ");
    const std::size_t test = line.find_first_not_of(' ');
    const bool names_a_test = test != std::string::npos && line.compare(test, 4, "Test") == 0 &&
                              line.find_first_not_of(' ', test + 4) == line.find('#', test);
    if (names_a_test && colon != std::string::npos) {
      tests[line.substr(colon + 2)] = current;
      current = Registered{};
      environment = false;
    } else if (line.rfind("Labels: ", 0) == 0) {
      std::istringstream words(line.substr(8));
      for (std::string w; words >> w;) current.labels.insert(w);
    } else if (line.find(": Environment variables:") != std::string::npos) {
      environment = true;
    } else if (environment && colon != std::string::npos && line.compare(colon, 3, ":  ") == 0) {
      current.environment.push_back(line.substr(colon + 3));
    } else {
      environment = false;
    }
  }
  return tests;
}

/// Configures the project in `folder` as scripts/sanitize.sh does (a sanitizer, its tiers, the
/// smoke set's program `driver`); nothing is built.
void Configure(const std::string& folder, const std::string& sanitizer, const std::string& tiers, const std::string& driver) {
  const test::RunResult r =
      test::RunCommand(Q(PRT_CMAKE_COMMAND) + " -S " + Q(test::SourceDir()) + " -B " + Q(folder) + " -G Ninja -D" + sanitizer +
                       "=ON " + Q("-DPRT_TEST_TIERS=" + tiers) + " " + Q("-DPRT_SMOKE_DRIVER=" + driver));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("tiers: every test file is in exactly one tier, every file a tier names exists, and no in-process file starts a process") {
    std::map<std::string, int> listed;
    for (const auto& entry : fs::recursive_directory_iterator(test::SourceDir() + "/tests")) {
      if (entry.path().filename() != "CMakeLists.txt") continue;
      const std::string text = ReadFile(entry.path().string()), folder = entry.path().parent_path().string();
      for (std::size_t at = text.find("prt_tests("); at != std::string::npos; at = text.find("prt_tests(", at + 1)) {
        if (at > 0 && text[at - 1] != '\n') continue;  // a call, not the function's definition or a comment
        std::istringstream words(text.substr(at + 10, text.find(')', at) - at - 10));
        std::string tier;
        words >> tier;
        CHECK((tier == "unit" || tier == "threads" || tier == "e2e" || tier == "readme" || tier == "slurm"));
        for (std::string file; words >> file;) {
          if (file == "PROGRAM") {  // PROGRAM NAME: the tier's program of that name
            words >> file;
            continue;
          }
          CAPTURE(file);
          CHECK(fs::exists(folder + "/" + file));
          ++listed[fs::weakly_canonical(folder + "/" + file).string()];
          // In-process: the link keeps tests/test_process.h out; nor may a file start a process
          // on its own.
          if (tier == "unit" || tier == "threads") {
            const std::string source = ReadFile(folder + "/" + file);
            for (const char* starts : {"std::system(", "popen(", "fork(", "execv", "core/child_process.h"}) {
              CAPTURE(starts);
              CHECK(source.find(starts) == std::string::npos);
            }
          }
        }
      }
    }
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(test::SourceDir() + "/tests")) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("test_", 0) != 0 || entry.path().extension() != ".cpp") continue;
      if (name == "test_support.cpp" || name == "test_process.cpp") continue;  // the helpers' libraries
      ++files;
      CAPTURE(entry.path().string());
      CHECK(listed[fs::weakly_canonical(entry.path()).string()] == 1);
    }
    CHECK(files > 100);
  }

  TEST_CASE("tiers: a sanitized folder registers its tiers and its pass's smoke set, run by another build's e2e program against its own prt") {
    const std::string dir = test::ScratchDir("tiers_configure");
    const std::string driver = fs::read_symlink("/proc/self/exe").string();  // this program: the e2e tier's
    for (const auto& [pass, sanitizer, tiers] :
         {std::tuple<std::string, std::string, std::string>{"asan", "PRT_SANITIZE", "unit;threads"},
          {"tsan", "PRT_TSAN", "threads"}}) {
      CAPTURE(pass);
      const std::string folder = dir + "/" + pass;
      Configure(folder, sanitizer, tiers, driver);
      const auto tests = Registrations(folder);
      const std::set<std::string> wanted = SmokeNames(pass);
      REQUIRE(wanted.size() >= 4);
      std::set<std::string> smoke;
      for (const auto& [name, t] : tests) {
        CAPTURE(name);
        if (!t.labels.count("smoke")) continue;
        smoke.insert(name);
        CHECK(t.labels.count("e2e") == 1);
        // The Release build's program runs it, against this folder's prt and scratch folders.
        CHECK(t.environment == std::vector<std::string>{"PRT_BINARY=" + folder + "/prt", "PRT_TEST_TMP=" + folder + "/test-tmp"});
      }
      CHECK(smoke == wanted);
      // Its tiers' programs are not built yet: a failing placeholder each, so that a tier whose
      // program is missing fails instead of running nothing; and no other tier's.
      for (const char* tier : {"unit", "threads", "e2e", "readme", "slurm"}) {
        CAPTURE(tier);
        const bool has = (";" + tiers + ";").find(std::string(";") + tier + ";") != std::string::npos;
        CHECK(tests.count(std::string("prt_") + tier + "_tests_NOT_BUILT") == (has ? 1u : 0u));
      }
    }
    // Without the Release build's program: one failing test says so, and no smoke test is lost
    // unseen.
    const std::string folder = dir + "/no_driver";
    Configure(folder, "PRT_TSAN", "threads", dir + "/no_such_build/prt_e2e_tests");
    const auto tests = Registrations(folder);
    CHECK(tests.count("prt_smoke_NO_DRIVER") == 1);
    for (const auto& [name, t] : tests) CHECK(t.labels.count("smoke") == 0);
  }
}

}  // namespace prt
