// ConvolvedRange (sh/convolved_range.h): the lowest and highest value of a light convolved with a
// zonal kernel, against closed forms. A light of bands 0 and 1, a + b z, convolved with k is
// k_0 a + k_1 b z: its extremes k_0 a -+ k_1 |b| lie at the poles, whatever the search does.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "core/constants.h"
#include "sh/convolved_range.h"
#include "sh/zonal.h"

using namespace prt;

namespace {

/// The search ends with compass steps of 1e-9 rad; at a smooth extremum the value it misses is
/// second order in the step (1e-18), and the SH sums round near 1e-15 of the values: 1e-12 is
/// far above both and far below any difference these cases test.
constexpr double kSearchTolerance = 1e-12;

/// Per channel c, the light a[c] + b[c] z as SH coefficients of bands 0 and 1:
/// Y_00 = 1/sqrt(4 pi), Y_10 = sqrt(3/(4 pi)) z.
ShRgb Linear(const glm::dvec3& a, const glm::dvec3& b) {
  ShRgb c(4, glm::dvec3(0.0));
  c[0] = a * std::sqrt(4.0 * kPi);
  c[2] = b * std::sqrt(4.0 * kPi / 3.0);
  return c;
}

}  // namespace

TEST_SUITE("sh") {
  TEST_CASE("ConvolvedRange: the light itself, and its irradiance, of a + b z in closed form") {
    // Red rings (1 - 1.2 = -0.2 at the south pole), green is the brightest (3 everywhere), blue
    // stays positive: the lowest and the highest come from different channels, which catches a
    // range taken on one channel or on their sum.
    const ShRgb light = Linear({1.0, 3.0, 1.0}, {1.2, 0.0, -0.5});
    const ShRange itself = ConvolvedRange(light, {1.0, 1.0});
    CHECK(itself.lowest == doctest::Approx(-0.2).epsilon(kSearchTolerance));
    CHECK(itself.highest == doctest::Approx(3.0).epsilon(kSearchTolerance));
    // The clamped cosine (A_0 = pi, A_1 = 2 pi/3) turns red's lowest to pi - 0.8 pi = 0.2 pi > 0:
    // the light rings, its irradiance does not. Catches a kernel left unapplied.
    const ShRange irradiance = ConvolvedRange(light, {ClampedCosineBand(0), ClampedCosineBand(1)});
    CHECK(irradiance.lowest == doctest::Approx(0.2 * kPi).epsilon(kSearchTolerance));
    CHECK(irradiance.highest == doctest::Approx(3.0 * kPi).epsilon(kSearchTolerance));
  }

  TEST_CASE("ConvolvedRange: a kernel that keeps band 1 and drops band 0 is odd: lowest = -highest") {
    // k = (0, 1): 1.2 z in red, -0.5 z in blue. Catches a kernel applied to the wrong bands.
    const ShRange r = ConvolvedRange(Linear({1.0, 3.0, 1.0}, {1.2, 0.0, -0.5}), {0.0, 1.0});
    CHECK(r.lowest == doctest::Approx(-1.2).epsilon(kSearchTolerance));
    CHECK(r.highest == doctest::Approx(1.2).epsilon(kSearchTolerance));
  }
}
