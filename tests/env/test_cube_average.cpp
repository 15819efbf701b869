// Cubemaps of texel averages (env/cubemap.h, CubemapFaceAverages) against the closed-form power
// of a small cap: averaged texels keep a sub-texel sun's power at every face size, where
// texel-centre samples catch it whole or miss it (what made `prt report`'s light table jump).
#include <doctest/doctest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "env/cube_faces.h"
#include "env/cubemap.h"

namespace prt {
namespace {

/// Sum over every texel of value x solid angle: the integral of the radiance the cubemap holds.
double Power(const std::array<ImageF, 6>& faces) {
  const int size = faces[0].width;
  double sum = 0.0;
  for (const ImageF& f : faces)
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) sum += f.at(col, row).x * TexelSolidAngle(col, row, size);
  return sum;
}

}  // namespace

TEST_SUITE("env") {
  TEST_CASE("cubemap: texel averages keep a small cap's power at every face size; centre samples do not") {
    // A cap of 2 degrees (the default sky's sun) towards a direction on no texel grid line.
    const double radius = 2.0 * kPi / 180.0;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.31, 0.52, -0.79));
    const auto cap = [&](const glm::dvec3& d) {
      return glm::dvec3(glm::dot(d, axis) >= std::cos(radius) ? 1.0 : 0.0);
    };
    const double exact = 2.0 * kPi * (1.0 - std::cos(radius));  // 3.8e-3 sr
    // Sub-texels 1/1024 of a face wide: about 700 across the cap's area, so its edge cells miss
    // or add a few tenths of a percent (measured at most 0.3%).
    constexpr double kAveragedTolerance = 0.01;
    // Texel-centre samples of an 11-degree texel: the cap is caught whole (a texel's 0.03 sr) or
    // missed (0), so at least one size is wrong by more than half.
    constexpr double kCentreMiss = 0.5;
    double worst_centre = 0.0;
    for (int size : {8, 16, 32, 64}) {
      CAPTURE(size);
      const double averaged = Power(CubemapFaceAverages(cap, size, 1024 / size));
      CHECK(std::abs(averaged / exact - 1.0) < kAveragedTolerance);
      worst_centre = std::max(worst_centre, std::abs(Power(CubemapFaceImages(cap, size)) / exact - 1.0));
    }
    CHECK(worst_centre > kCentreMiss);
    // supersample 1 is the texel-centre cubemap, byte for byte.
    const auto one = CubemapFaceAverages(cap, 16, 1), centre = CubemapFaceImages(cap, 16);
    for (int k = 0; k < 6; ++k) CHECK(one[k].pixels == centre[k].pixels);
  }
}

}  // namespace prt
