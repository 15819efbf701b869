// How far a change to one header reaches: every source file of src/, bench/ and tests/ is read for
// its #include "..." lines, and for each header of src/ the translation units that include it,
// directly or through other headers, are counted. No header may reach most of the tree, or a
// change to it rebuilds most of every build (core/image.h reached 239 of 323 objects through
// geometry/mesh.h, which included texture/texture.h for a pointer; a declaration does).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "tests/test_support.h"

namespace prt {
namespace {
namespace fs = std::filesystem;

/// At most this share of the translation units may include one header of src/ (the widest now,
/// sh/coeffs.h, reaches 47%: the SH coefficients are in most of the maths).
constexpr double kMostOfTheTree = 0.6;

/// The project's own files each file includes, resolved against src/ and the repository root.
std::map<std::string, std::vector<std::string>> IncludeGraph() {
  const std::string root = test::SourceDir();
  std::map<std::string, std::vector<std::string>> graph;
  for (const char* folder : {"src", "bench", "tests"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root + "/" + folder)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".h" && ext != ".cpp") continue;
      std::vector<std::string>& includes = graph[entry.path().string()];
      std::ifstream in(entry.path());
      for (std::string line; std::getline(in, line);) {
        if (line.rfind("#include \"", 0) != 0) continue;
        const std::string name = line.substr(10, line.find('"', 10) - 10);
        for (const std::string& base : {root + "/src/", root + "/"})
          if (fs::exists(base + name)) {
            includes.push_back(fs::path(base + name).lexically_normal().string());
            break;
          }
      }
    }
  }
  return graph;
}

/// Every file `file` includes, directly or not (memoised in `reach`).
const std::set<std::string>& Reach(const std::string& file, const std::map<std::string, std::vector<std::string>>& graph,
                                   std::map<std::string, std::set<std::string>>& reach) {
  const auto known = reach.find(file);
  if (known != reach.end()) return known->second;
  reach[file];  // empty while it is being visited: an include cycle ends here
  std::set<std::string> found;
  const auto edges = graph.find(file);
  if (edges != graph.end())
    for (const std::string& included : edges->second) {
      found.insert(included);
      const std::set<std::string>& further = Reach(included, graph, reach);
      found.insert(further.begin(), further.end());
    }
  return reach[file] = found;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("header reach: no header of src/ is included, directly or not, by most of the translation units") {
    const auto graph = IncludeGraph();
    std::map<std::string, std::set<std::string>> reach;
    std::map<std::string, int> units_of;
    int units = 0;
    for (const auto& [file, includes] : graph) {
      if (fs::path(file).extension() != ".cpp") continue;
      ++units;
      for (const std::string& header : Reach(file, graph, reach)) ++units_of[header];
    }
    REQUIRE(units > 250);
    const std::string src = test::SourceDir() + "/src/";
    int widest = 0;
    for (const auto& [header, count] : units_of) {
      if (header.rfind(src, 0) != 0) continue;
      CAPTURE(header);
      CAPTURE(count);
      CHECK(count <= kMostOfTheTree * units);
      widest = std::max(widest, count);
    }
    // The count is real: some header is in a good share of the tree (sh/coeffs.h: 47%).
    CHECK(widest > units / 4);
  }
}

}  // namespace prt
