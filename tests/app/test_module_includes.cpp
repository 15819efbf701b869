// Dependencies point one way: scripts/check-includes.cmake reads every #include of src/ and
// bench/ against the table of src/modules.cmake. Run here on the project itself (it must pass),
// and on small made-up trees, each with one fault it must name.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;
using test::Q;

test::RunResult CheckIncludes(const std::string& root) {
  return test::RunCommand(Q(PRT_CMAKE_COMMAND) + " -D ROOT=" + Q(root) + " -P " +
                          Q(test::SourceDir() + "/scripts/check-includes.cmake"));
}

/// A project of three folders, low <- mid <- top, each file including what the table allows,
/// with `table` as its src/modules.cmake; the files under `extra` added (path, text).
std::string MadeUpTree(const std::string& name, const std::string& table,
                       const std::vector<std::pair<std::string, std::string>>& extra = {}) {
  const std::string root = test::ScratchDir(name);
  fs::create_directories(root + "/src/low");
  fs::create_directories(root + "/src/mid");
  fs::create_directories(root + "/src/top");
  fs::create_directories(root + "/bench");
  WriteFileAtomic(root + "/src/modules.cmake", "set(PRT_MODULES\n" + table + ")\n");
  WriteFileAtomic(root + "/src/low/low.h", "#pragma once\n#include <vector>\n");
  WriteFileAtomic(root + "/src/mid/mid.h", "#pragma once\n#include \"low/low.h\"\n");
  WriteFileAtomic(root + "/src/mid/mid.cpp", "#include \"mid/mid.h\"\n");
  WriteFileAtomic(root + "/src/top/top.cpp", "#include \"mid/mid.h\"\n  #  include \"low/low.h\"\n");
  WriteFileAtomic(root + "/bench/bench.cpp", "#include \"top/top.h\"\n");
  for (const auto& [path, text] : extra) {
    fs::create_directories(fs::path(root + "/" + path).parent_path());
    WriteFileAtomic(root + "/" + path, text);
  }
  return root;
}

/// Each folder and its dependencies as words, in order, from the lines `"folder: deps"` of
/// src/modules.cmake.
std::vector<std::pair<std::string, std::string>> TableOfModulesCmake() {
  const std::string text = ReadFile(test::SourceDir() + "/src/modules.cmake");
  std::vector<std::pair<std::string, std::string>> table;
  const std::regex entry("\"([a-z_0-9]+):([^\"]*)\"");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it) {
    std::istringstream words((*it)[2].str());
    std::string joined;
    for (std::string w; words >> w;) joined += (joined.empty() ? "" : " ") + w;
    table.emplace_back((*it)[1], joined);
  }
  return table;
}

/// The same from the table docs/ARCHITECTURE.md draws (the block that starts "folder  includes").
std::vector<std::pair<std::string, std::string>> TableOfArchitecture() {
  std::istringstream doc(ReadFile(test::SourceDir() + "/docs/ARCHITECTURE.md"));
  std::vector<std::pair<std::string, std::string>> table;
  bool inside = false;
  for (std::string line; std::getline(doc, line);) {
    if (!inside) {
      inside = std::regex_match(line, std::regex("folder +includes *"));
      continue;
    }
    if (line.rfind("```", 0) == 0) break;
    std::istringstream words(line);
    std::string folder, joined;
    words >> folder;
    for (std::string w; words >> w;) joined += (joined.empty() ? "" : " ") + w;
    table.emplace_back(folder, joined);
  }
  return table;
}

const std::string kTable = "  \"low:\"\n  \"mid: low\"\n  \"top: low mid\"\n  \"bench: top\"\n";

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("module includes: docs/ARCHITECTURE.md draws the table the build checks") {
    const auto cmake = TableOfModulesCmake(), doc = TableOfArchitecture();
    REQUIRE(cmake.size() >= 10);
    CHECK(doc == cmake);  // the same rows in the same order: each folder after those it includes
    const std::map<std::string, std::string> drawn(doc.begin(), doc.end());
    for (const auto& [folder, deps] : cmake) {
      CAPTURE(folder);
      CHECK(drawn.count(folder) == 1);
      if (drawn.count(folder)) CHECK(drawn.at(folder) == deps);
    }
  }

  TEST_CASE("architecture: docs/ARCHITECTURE.md names every header of src/ and bench/") {
    // Named as folder/name.h anywhere, or as name.h in its folder's own section ("## src/F").
    const std::string doc = ReadFile(test::SourceDir() + "/docs/ARCHITECTURE.md");
    std::map<std::string, std::string> sections;  // "src/F" or "bench" -> its text
    std::string current;
    std::istringstream lines(doc);
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("## ", 0) == 0) {
        current = line.substr(3);
        while (!current.empty() && current.back() == '/') current.pop_back();
      }
      sections[current] += line + "\n";
    }
    int headers = 0;
    for (const std::string top : {"src", "bench"})
      for (const auto& entry : fs::recursive_directory_iterator(test::SourceDir() + "/" + top)) {
        if (entry.path().extension() != ".h") continue;
        ++headers;
        const std::string folder = fs::relative(entry.path().parent_path(), test::SourceDir()).string();
        const std::string name = entry.path().filename().string();
        const std::string qualified = entry.path().parent_path().filename().string() + "/" + name;
        CAPTURE(folder);
        CAPTURE(name);
        CHECK((doc.find(qualified) != std::string::npos || sections[folder].find(name) != std::string::npos));
      }
    CHECK(headers > 100);
  }

  TEST_CASE("module includes: the project's own includes all point down its table") {
    const test::RunResult r = CheckIncludes(test::SourceDir());
    INFO(r.err);
    CHECK(r.exit_code == 0);
  }

  TEST_CASE("module includes: a made-up tree that follows its table passes") {
    const test::RunResult r = CheckIncludes(MadeUpTree("includes-good", kTable));
    INFO(r.err);
    CHECK(r.exit_code == 0);
  }

  TEST_CASE("module includes: an upward include is named with its file and line") {
    const std::string root = MadeUpTree("includes-up", kTable,
                                        {{"src/low/low.cpp", "#include \"low/low.h\"\n\n#include \"top/top.h\"\n"}});
    const test::RunResult r = CheckIncludes(root);
    CHECK(r.exit_code != 0);
    CHECK(r.err.find("src/low/low.cpp:3: includes top/top.h") != std::string::npos);
    CHECK(r.err.find("low may include only") != std::string::npos);
  }

  TEST_CASE("module includes: an include of a folder not declared, even a lower one, fails") {
    // mid declares low only; an include of top from bench's side is fine, but mid -> top is not.
    const std::string root = MadeUpTree("includes-undeclared", "  \"low:\"\n  \"mid: low\"\n  \"top: mid\"\n  \"bench: top\"\n");
    const test::RunResult r = CheckIncludes(root);  // top.cpp includes low/low.h, which top does not list
    CHECK(r.exit_code != 0);
    CHECK(r.err.find("src/top/top.cpp:2: includes low/low.h") != std::string::npos);
  }

  TEST_CASE("module includes: bench is checked like a folder of src/") {
    const std::string root = MadeUpTree("includes-bench", "  \"low:\"\n  \"mid: low\"\n  \"top: low mid\"\n  \"bench: mid\"\n",
                                        {{"bench/more.cpp", "#include \"mid/mid.h\"\n"}});
    const test::RunResult r = CheckIncludes(root);
    CHECK(r.exit_code != 0);
    CHECK(r.err.find("bench/bench.cpp:1: includes top/top.h") != std::string::npos);
  }

  TEST_CASE("module includes: a cycle in the table, an unlisted folder and an unused dependency each fail") {
    SUBCASE("a folder depending on one listed after it") {
      const test::RunResult r =
          CheckIncludes(MadeUpTree("includes-cycle", "  \"low: mid\"\n  \"mid: low\"\n  \"top: low mid\"\n  \"bench: top\"\n"));
      CHECK(r.exit_code != 0);
      CHECK(r.err.find("low depends on mid, which is not listed before it") != std::string::npos);
    }
    SUBCASE("a folder of src/ the table does not list") {
      const test::RunResult r =
          CheckIncludes(MadeUpTree("includes-unlisted", kTable, {{"src/extra/extra.h", "#pragma once\n"}}));
      CHECK(r.exit_code != 0);
      CHECK(r.err.find("src/extra: a folder that src/modules.cmake does not list") != std::string::npos);
    }
    SUBCASE("a dependency no file uses") {
      const test::RunResult r =
          CheckIncludes(MadeUpTree("includes-unused", "  \"low:\"\n  \"mid: low\"\n  \"top: low mid\"\n  \"bench: low top\"\n"));
      CHECK(r.exit_code != 0);
      CHECK(r.err.find("bench lists low, which none of its files includes") != std::string::npos);
    }
  }
}

}  // namespace prt
