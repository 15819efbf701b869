// The page of prt view is embedded in the program at build time (scripts/embed-files.cmake): a
// change to one of its files embeds it again. (What is served by name: test_page.cpp.)
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/test_process.h"

namespace prt {

TEST_SUITE("view") {
TEST_CASE("the build embeds the page again when one of its files changes") {
  // src/view's CMake rules in a project of their own, with a stand-in for the library they add
  // to: built once, a page file changed, built again; the generated source must hold the change.
  namespace fs = std::filesystem;
  const std::string dir = test::ScratchDir("page_embed");
  fs::create_directories(dir + "/scripts");
  fs::create_directories(dir + "/src");
  fs::copy(test::SourceDir() + "/src/view", dir + "/src/view", fs::copy_options::recursive);
  fs::copy_file(test::SourceDir() + "/scripts/embed-files.cmake", dir + "/scripts/embed-files.cmake");
  std::ofstream(dir + "/CMakeLists.txt")
      << "cmake_minimum_required(VERSION 3.20)\nproject(embed CXX)\nadd_library(prtapp STATIC)\n"
         "add_library(prt::httplib INTERFACE IMPORTED)\n"
         "add_subdirectory(src/view)\n";
  const std::string cmake = PRT_CMAKE_COMMAND;
  const auto build = [&] {
    const test::RunResult r = test::RunCommand(test::Q(cmake) + " --build " + test::Q(dir + "/build") +
                                               " --target prt_view_page");
    INFO(r.out, r.err);
    REQUIRE(r.exit_code == 0);
    std::ifstream in(dir + "/build/src/view/embedded_page.cpp");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const test::RunResult configure =
      test::RunCommand(test::Q(cmake) + " -S " + test::Q(dir) + " -B " + test::Q(dir + "/build"));
  INFO(configure.out, configure.err);
  REQUIRE(configure.exit_code == 0);
  const std::string before = build();
  CHECK(before.find("\"view.js\"") != std::string::npos);
  // "//!" in bytes, as the generated source writes them: absent, then present.
  const std::string marker = "0x2f,0x2f,0x21,";
  CHECK(before.find(marker) == std::string::npos);
  std::ofstream(dir + "/src/view/page/view.js", std::ios::app) << "//!\n";
  const std::string after = build();
  CHECK(after.find(marker) != std::string::npos);
  CHECK(after != before);
}
}

}  // namespace prt
