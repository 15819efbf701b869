// The test runner itself: tests/discover_tests.cmake registers every case of a test program with
// CTest, labelled with its suite and its tier, from one XML listing; for a sanitizer pass it
// registers only the smoke set that tests/smoke.txt names, pointed at another prt; a name with a
// comma must still select its case (doctest splits filters at commas), and a filter that selects
// nothing fails (tests/main.cpp). This program is the e2e tier's.
#include <doctest/doctest.h>

#include <cctype>
#include <sstream>
#include <string>

#include <unistd.h>

#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace {

/// The test cases that `listing` (a test program's --list-test-cases) names, one a line.
int CountListed(const std::string& listing) {
  std::istringstream lines(listing);
  int n = 0;
  for (std::string line; std::getline(lines, line);)
    n += !line.empty() && line.rfind("[doctest]", 0) != 0 && line.rfind("=====", 0) != 0;
  return n;
}

/// How many times `needle` occurs in `text`.
std::size_t Count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

/// discover_tests.cmake run as the build runs it, over `program` (tier e2e), writing `ctest_file`;
/// `before` is put ahead of the command (environment variables), `defines` among its -D options.
prt::test::RunResult Discover(const std::string& program, const std::string& working_dir, const std::string& ctest_file,
                              const std::string& before = "", const std::string& defines = "") {
  using prt::test::Q;
  return prt::test::RunCommand(before + Q(PRT_CMAKE_COMMAND) + " -D TEST_EXECUTABLE=" + Q(program) +
                               " -D TIER=e2e -D TEST_WORKING_DIR=" + Q(working_dir) + " -D CTEST_FILE=" + Q(ctest_file) +
                               " -D TEST_TIMEOUT=600 -D SKIP_RETURN_CODE=77" + defines + " -P " +
                               Q(prt::test::SourceDir() + "/tests/discover_tests.cmake"));
}

}  // namespace

TEST_SUITE("core") {
  TEST_CASE("runner: every case is a CTest test under its suite and tier; a name with commas, like this one, or <, >, &, &lt; [ ], \" and ' selects it") {
    // The name holds every character the registration must carry through: commas (doctest's
    // filter separator), ';' (a CMake list separator), '[' ']' (which CMake lists keep
    // together), what XML escapes, and the text of an escape (&lt;, which the XML writes as
    // &amp;lt;: undone in the wrong order it would come back as '<').
    const std::string name = doctest::getContextOptions()->currentTest->m_name;
    for (char c : {',', ';', '<', '>', '&', '[', ']', '"', '\''}) REQUIRE(name.find(c) != std::string::npos);
    REQUIRE(name.find("&lt;") != std::string::npos);
    const std::string self = "/proc/" + std::to_string(::getpid()) + "/exe";
    const std::string dir = prt::test::ScratchDir("runner");
    REQUIRE(Discover(self, dir, dir + "/cases.cmake").exit_code == 0);
    const std::string cases = prt::ReadFile(dir + "/cases.cmake");

    // One add_test per case the program lists, each with its suite and its tier as the labels.
    const auto listed = prt::test::RunCommand(self + " --list-test-cases --no-intro=true");
    REQUIRE(listed.exit_code == 0);
    const std::size_t add_tests = Count(cases, "add_test(");
    CHECK(add_tests == std::size_t(CountListed(listed.out)));
    CHECK(add_tests > 100);
    std::string filter = name;
    for (std::size_t at = filter.find(','); at != std::string::npos; at = filter.find(',', at + 2)) filter.insert(at, "\\");
    CHECK(cases.find("add_test([==[" + name + "]==] [==[" + self + "]==] [==[--test-case=" + filter + "]==]") !=
          std::string::npos);
    const auto props = cases.find("set_tests_properties([==[" + name + "]==]");
    REQUIRE(props != std::string::npos);
    const std::string properties = cases.substr(props, cases.find('\n', props) - props);
    CHECK(properties.find("LABELS [==[core;e2e]==]") != std::string::npos);
    CHECK(properties.find("SKIP_RETURN_CODE 77") != std::string::npos);  // the runner's "skipped"
    CHECK(properties.find("ENVIRONMENT") == std::string::npos);  // only the smoke set's are pointed elsewhere
    // Another suite's case gets its own label, not the first one seen.
    CHECK(cases.find("LABELS [==[app;e2e]==]") != std::string::npos);

    // Without the course data the same cases are registered: those that need it are listed,
    // so that CTest reports them as skipped rather than leaving them out.
    REQUIRE(Discover(self, dir, dir + "/no_data.cmake", "PRT_SHARED_DATA=none PRT_REQUIRE_SHARED_DATA=0 ").exit_code == 0);
    const std::string no_data = prt::ReadFile(dir + "/no_data.cmake");
    CHECK(no_data == cases);
    CHECK(no_data.find("add_test([==[course files: mary's undefined material is said once, and her files load in the "
                       "viewer]==]") != std::string::npos);

    // A sanitizer pass's smoke set: only the cases the list names for that pass, this one
    // among them (its name's characters read from the list as from the listing), each with the
    // smoke label and the variables that point it at another prt; a name the program lacks fails.
    const auto smoke = [&](const std::string& list, const std::string& out, const std::string& pass = "asan") {
      prt::WriteFileAtomic(dir + "/smoke.txt", list);
      return Discover(self, dir, dir + "/" + out, "",
                      " -D SMOKE_LIST=" + prt::test::Q(dir + "/smoke.txt") + " -D SMOKE_PASS=" + pass +
                          " '-D SMOKE_ENVIRONMENT=PRT_BINARY=/x/prt;PRT_TEST_TMP=/x/tmp'");
    };
    const std::string other = "runner: the small scene of the tests is small";
    REQUIRE(smoke("# a comment\nasan: " + name + "\ntsan: " + other + "\n", "smoke.cmake").exit_code == 0);
    const std::string smoke_cases = prt::ReadFile(dir + "/smoke.cmake");
    CHECK(Count(smoke_cases, "add_test(") == 1);  // the tsan line is another pass's
    CHECK(smoke_cases.find("add_test([==[" + name + "]==]") != std::string::npos);
    CHECK(smoke_cases.find("LABELS [==[core;e2e;smoke]==]") != std::string::npos);
    CHECK(smoke_cases.find("ENVIRONMENT [==[PRT_BINARY=/x/prt;PRT_TEST_TMP=/x/tmp]==]") != std::string::npos);
    // The other pass takes the other line.
    REQUIRE(smoke("# a comment\nasan: " + name + "\ntsan: " + other + "\n", "smoke_tsan.cmake", "tsan").exit_code == 0);
    const std::string tsan_cases = prt::ReadFile(dir + "/smoke_tsan.cmake");
    CHECK(tsan_cases.find("add_test([==[" + other + "]==]") != std::string::npos);
    CHECK(tsan_cases.find("add_test([==[" + name + "]==]") == std::string::npos);
    const auto stale = smoke("asan: no test has this name\n", "stale.cmake");
    CHECK(stale.exit_code != 0);
    // CMake wraps its messages' lines: compared with every run of white space made one space.
    std::string said;
    for (char c : stale.err)
      if (!std::isspace(static_cast<unsigned char>(c))) said += c;
      else if (!said.empty() && said.back() != ' ') said += ' ';
    CHECK(said.find("names 'no test has this name' for asan") != std::string::npos);

    // The registered filter selects exactly this case.
    const auto selected = prt::test::RunCommand(self + " " + prt::test::Q("--test-case=" + filter) +
                                                " --list-test-cases --no-intro=true");
    CHECK(selected.exit_code == 0);
    CHECK(CountListed(selected.out) == 1);
    CHECK(selected.out.find(name) != std::string::npos);
    // A filter that selects no case fails the run instead of passing without a test.
    const auto none = prt::test::RunCommand(self + " --test-case='no case has this name' --no-intro=true");
    CHECK(none.exit_code == 1);
    CHECK(none.err.find("no test case matches the filters") != std::string::npos);
  }

  TEST_CASE("runner: the small scene of the tests is small") {
    // The scene: the knot and the ground, 241 vertices, as --mesh loads it.
    const std::string dir = prt::test::ScratchDir("runner_small_scene");
    const auto r = prt::test::RunPrt("precompute --quiet --transport unshadowed --mesh " +
                                     prt::test::Q(prt::test::WriteSmallScene(dir)) + " --out " + prt::test::Q(dir + "/out"));
    REQUIRE(r.exit_code == 0);
    std::istringstream transport(prt::ReadFile(dir + "/out/transport.txt"));
    int vertices = 0;
    transport >> vertices;
    CHECK(vertices == 241);
  }
}
