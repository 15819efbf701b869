#include "tests/app/viewer_files.h"

#include <cstdlib>
#include <fstream>

#include <doctest/doctest.h>

namespace prt::test {

std::vector<std::vector<double>> ReadLikeTheViewer(const std::string& path, std::size_t per_row,
                                                   ViewerHeader header) {
  std::ifstream in(path);
  REQUIRE(in.good());
  std::string line;
  if (header == ViewerHeader::kSkip) std::getline(in, line);  // the vertex count: the viewer ignores it
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<double> row;
    std::size_t start = 0;
    for (;;) {
      const std::size_t space = line.find(' ', start);
      const std::string token = line.substr(start, space == std::string::npos ? std::string::npos : space - start);
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      CAPTURE(line);
      REQUIRE_FALSE(token.empty());
      REQUIRE(*end == '\0');
      row.push_back(v);
      if (space == std::string::npos) break;
      start = space + 1;
    }
    CAPTURE(line);
    REQUIRE(row.size() == per_row);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace prt::test
