#include "precompute_io/light_txt.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.h"

namespace prt {

std::string FormatLightTxt(const ShRgb& coeffs) {
  std::string out;
  char line[128];
  for (const auto& c : coeffs) {
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", c.x, c.y, c.z);
    out += line;
  }
  return out;
}

ShRgb ParseLightTxt(const std::string& text, const std::string& path) {
  ShRgb coeffs;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream ls(line);
    glm::dvec3 c;
    std::string extra;
    if (!(ls >> c.x >> c.y >> c.z) || (ls >> extra) || !std::isfinite(c.x) || !std::isfinite(c.y) ||
        !std::isfinite(c.z))
      throw Error(path + ":" + std::to_string(number) + ": expected three finite numbers `R G B`");
    coeffs.push_back(c);
  }
  if (LmaxOfCount(coeffs.size()) < 0)
    throw Error(path + ": " + std::to_string(coeffs.size()) +
                " coefficient lines (expected a square count: 1, 4, 9, 16, ...)");
  return coeffs;
}

}  // namespace prt
