// The test runner itself (tests/main.cpp): CTest's discovery asks each case's suite, for its
// label, with the case's name as an unescaped filter; a name with a comma must still be found.
#include <doctest/doctest.h>

#include <string>

#include <unistd.h>

#include "tests/test_support.h"

TEST_SUITE("core") {
  TEST_CASE("runner: a test case whose name has commas, like this one, is labelled with its suite") {
    const std::string name = doctest::getContextOptions()->currentTest->m_name;
    REQUIRE(name.find(',') != std::string::npos);
    const auto r = prt::test::RunCommand("/proc/" + std::to_string(::getpid()) + "/exe " +
                                         prt::test::Q("--test-case=" + name) + " --list-test-suites --no-intro=true");
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("\ncore\n") != std::string::npos);
  }
}
