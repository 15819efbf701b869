#include "tests/golden.h"

#include <cstdlib>
#include <filesystem>

#include <doctest/doctest.h>

#include "core/error.h"
#include "io/png_io.h"
#include "raster/image_diff.h"
#include "tests/test_support.h"

namespace prt::test {
namespace fs = std::filesystem;

void CheckGolden(const std::string& name, const Image8& actual, const GoldenLimits& limits) {
  const std::string golden = SourceDir() + "/tests/golden/" + name + ".png";
  const char* update = std::getenv("PRT_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    fs::create_directories(fs::path(golden).parent_path());
    WritePng(golden, actual);
    MESSAGE("golden written: " << golden);
    return;
  }
  if (!fs::exists(golden)) {
    FAIL_CHECK("missing golden " << golden << " (run the tests with PRT_UPDATE_GOLDEN=1 to create it)");
    return;
  }
  const Image8 expected = ReadPng(golden);
  if (expected.width != actual.width || expected.height != actual.height) {
    FAIL_CHECK("golden " << golden << " is " << expected.width << "x" << expected.height << ", actual "
                         << actual.width << "x" << actual.height);
    return;
  }
  const DiffMetrics m = CompareImages(actual, expected);
  const bool ok = m.max_abs <= limits.max_abs && m.mean_abs <= limits.mean_abs;
  if (!ok) {
    const std::string dir = SourceDir() + "/out/test-failures";
    fs::create_directories(dir);
    WritePng(dir + "/" + name + "_actual.png", actual);
    WritePng(dir + "/" + name + "_expected.png", expected);
    WritePng(dir + "/" + name + "_diff.png", AmplifiedDifference(actual, expected));
    FAIL_CHECK("golden " << name << ": " << FormatDiffMetrics(m) << " exceeds max_abs " << limits.max_abs
                         << ", mean_abs " << limits.mean_abs << "; see " << dir << "/" << name
                         << "_{actual,expected,diff}.png");
  }
}

RenderOptions GoldenFrame() {
  RenderOptions o;
  o.tonemap = ToneCurve::kSrgb;
  o.exposure = 0.0;
  o.ssaa = 1;
  o.width = o.height = 96;
  o.eye = glm::dvec3(0.0, 3.0, 7.0);
  o.target = glm::dvec3(0.0, 0.8, 0.0);
  o.fov = 40.0;
  return o;
}

}  // namespace prt::test
