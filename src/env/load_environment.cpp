#include "env/load_environment.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

#include "core/error.h"
#include "env/cubemap.h"
#include "env/equirect.h"
#include "env/procedural.h"

namespace prt {
namespace fs = std::filesystem;
namespace {

double ParseValue(const std::string& spec, const std::string& key, const std::string& text, double lo,
                  double hi) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  std::ostringstream ss;
  ss << spec << ": " << key;
  if (text.empty()) ss << " has no value";
  else if (end != text.c_str() + text.size() || !std::isfinite(v) || text.find_first_of("xXpP") != std::string::npos)
    ss << " '" << text << "' is not a number";
  else if (v < lo || v > hi) ss << " '" << text << "' is out of range";
  else return v;
  ss << " (expected a number from " << lo << " to " << hi << ")";
  throw Error(ss.str());
}

SkyParams ParseSky(const std::string& spec, const std::string& params) {
  SkyParams p;
  std::stringstream ss(params);
  std::set<std::string> seen;
  for (std::string item; std::getline(ss, item, ',');) {
    const auto eq = item.find('=');
    const std::string key = item.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
    if (!seen.insert(key).second) throw Error(spec + ": " + key + " is given twice (expected each parameter once)");
    if (key == "sun") p.sun = ParseValue(spec, key, value, 0.0, 1e6);
    else if (key == "elevation") p.elevation = ParseValue(spec, key, value, -90.0, 90.0);
    else if (key == "azimuth") p.azimuth = ParseValue(spec, key, value, -360.0, 360.0);
    else if (key == "radius") p.radius = ParseValue(spec, key, value, 0.05, 45.0);
    else
      throw Error(spec + ": unknown sky parameter '" + key + "' (expected sun, elevation, azimuth or radius)");
  }
  return p;
}

}  // namespace

const std::vector<std::string>& BuiltinEnvironmentNames() {
  static const std::vector<std::string> names = {"furnace", "sky"};
  return names;
}

BuiltinEnvironment ParseBuiltinEnvironment(const std::string& spec) {
  const auto colon = spec.find(':');
  BuiltinEnvironment b;
  b.name = spec.substr(0, colon);
  const std::string params = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (b.name == "furnace") b.furnace = params.empty() ? 1.0 : ParseValue(spec, "value", params, 0.0, 1e12);
  else if (b.name == "sky") b.sky = ParseSky(spec, params);
  else
    throw Error(spec + ": no such file, folder or built-in environment (expected a cubemap folder, an "
                       "equirectangular .hdr/.exr/.png/.jpg file, or one of furnace, sky)");
  return b;
}

std::unique_ptr<Environment> LoadEnvironment(const std::string& spec, CubeLayout layout) {
  std::error_code ec;
  if (fs::is_directory(spec, ec)) return LoadCubemap(spec, layout);
  if (fs::exists(spec, ec)) {
    RefuseCubemapFace(spec);  // one face of a cubemap is no panorama
    return LoadEquirect(spec);
  }
  const BuiltinEnvironment b = ParseBuiltinEnvironment(spec);
  return b.name == "furnace" ? MakeFurnace(b.furnace) : MakeSky(b.sky);
}

}  // namespace prt
