#pragma once
/// \file
/// Helpers shared by the tests: where the shared course data is, scratch folders, and running the
/// `prt` binary the way a user does.

#include <optional>
#include <string>

namespace prt::test {

/// The project's source folder (for fixtures in tests/data).
std::string SourceDir();
/// A fixture path: SourceDir()/tests/data/<relative>.
std::string Fixture(const std::string& relative);

/// `../shared/data` beside the project if it exists. Tests that need it skip with a message
/// when it is absent (a user's fresh clone does not have it).
std::optional<std::string> SharedData();

/// An empty scratch folder for one test, under the build folder's test-tmp/.
std::string ScratchDir(const std::string& name);

struct RunResult {
  int exit_code = -1;
  std::string out;  ///< stdout
  std::string err;  ///< stderr
};
/// `text` as one single-quoted shell word (a quote inside it included).
std::string ShellQuote(const std::string& text);

/// Runs the `prt` binary (path from the PRT_BINARY environment variable, set by CTest) with a
/// shell-quoted argument string. Returns nullopt if the binary is not known.
std::optional<RunResult> RunPrt(const std::string& arguments);

}  // namespace prt::test

/// Skips the rest of a test case with a message when `../shared/data` is absent.
#define PRT_SHARED_DATA_OR_SKIP(var)                                      \
  const auto var##_opt = ::prt::test::SharedData();                       \
  if (!var##_opt) {                                                       \
    MESSAGE("skipped: ../shared/data is absent (course data not present)"); \
    return;                                                               \
  }                                                                       \
  const std::string var = *var##_opt
