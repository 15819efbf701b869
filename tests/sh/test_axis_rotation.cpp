// Turning the light about a fixed axis (sh/axis_rotation.h), above all about axes that point down:
// -Z (the polar shortcut, which carries the axis's sign), -Y, -X and a general axis with every
// component negative, with the positive axes beside them. Checked against routes that share
// nothing with the code under test:
//  - a light given by its coefficients c is the band-limited function f(d) = sum_k c_k Y_k(d), so
//    the turned light must reconstruct to f(R^T d) at every d (L'(d) = L(R^T d), sh/rotation.h),
//    with R written out here by Rodrigues' formula, not taken from sh/rotation.h;
//  - a band-1 light is the linear function a.d, and turning it is the 3x3 matrix R on a: quarter
//    and third turns whose results are worked out by hand.
// (tests/render/test_light_turn.cpp checks that the drawn background turns with the SH light.)
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/rng.h"
#include "sh/axis_rotation.h"
#include "sh/basis.h"
#include "tests/sh/sh_test_util.h"

using namespace prt;

namespace {

// Bands 0..4: band matrices of every size up to 9 x 9 take part.
constexpr int kLmax = 4;
// The turned light against f(R^T d): one band-limited function evaluated two ways, coefficients
// of size up to 2.3, 25 terms; measured 3.1e-15 at worst.
constexpr double kBandLimitedTolerance = 1e-12;

using test::EvaluateSh;
using test::RandomDirection;
using test::RandomLight;

/// The axes of the test: the negative ones first (not unit length, on purpose, for two).
const std::vector<glm::dvec3>& Axes() {
  static const std::vector<glm::dvec3> axes = {{0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, {-1, -2, -2},
                                               {0, 0, -3}, {0.3, -0.5, -0.8}, {0, 0, 1}, {0, 1, 0},
                                               {1, 0, 0},  {1, 2, 2}};
  return axes;
}

/// R d for the turn by `a` radians (right-handed) about `axis`: Rodrigues' formula,
/// d cos a + (k x d) sin a + k (k.d)(1 - cos a).
glm::dvec3 TurnedByHand(const glm::dvec3& axis, double a, const glm::dvec3& d) {
  const glm::dvec3 k = axis / std::sqrt(glm::dot(axis, axis));
  return d * std::cos(a) + glm::cross(k, d) * std::sin(a) + k * glm::dot(k, d) * (1.0 - std::cos(a));
}

}  // namespace

TEST_SUITE("sh") {
  TEST_CASE("axis rotation: the light turned about -Z, -Y, -X and axes pointing down is f(R^T d), R by hand") {
    const ShRgb light = RandomLight(kLmax, 1);
    Pcg32 rng(21, 0);
    std::vector<glm::dvec3> directions(24);
    for (auto& d : directions) d = RandomDirection(rng);
    for (const glm::dvec3& axis : Axes()) {
      const AxisRotation rotation(axis, kLmax);
      for (double angle : {0.4, 1.3, -2.2, 2.9, 7.0}) {
        const ShRgb turned = rotation.Rotate(light, angle);
        double worst = 0.0;
        for (const glm::dvec3& d : directions) {
          const glm::dvec3 expected = EvaluateSh(light, TurnedByHand(axis, -angle, d));  // f(R^T d)
          const glm::dvec3 got = EvaluateSh(turned, d);
          for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(got[ch] - expected[ch]));
        }
        INFO("axis (" << axis.x << ", " << axis.y << ", " << axis.z << "), angle " << angle << ": worst " << worst);
        CHECK(worst < kBandLimitedTolerance);
      }
    }
  }

  TEST_CASE("axis rotation: a band-1 light's direction turns as worked out by hand about negative axes") {
    // The band-1 basis is K (-y, z, -x), K = sqrt(3 / (4 pi)) (with the Condon-Shortley sign),
    // so coefficients (-a.y, a.z, -a.x) are the light K a.d, which turns into K (R a).d: its
    // coefficients are those of R a.
    const double K = std::sqrt(3.0 / (4.0 * kPi));
    const std::vector<double> yx = EvalBasis(1, {1, 0, 0}), yy = EvalBasis(1, {0, 1, 0}), yz = EvalBasis(1, {0, 0, 1});
    REQUIRE(std::abs(yy[1] + K) < kBandLimitedTolerance);
    REQUIRE(std::abs(yz[2] - K) < kBandLimitedTolerance);
    REQUIRE(std::abs(yx[3] + K) < kBandLimitedTolerance);
    const auto band1 = [](const glm::dvec3& a) {
      return ShRgb{glm::dvec3(0.0), glm::dvec3(-a.y), glm::dvec3(a.z), glm::dvec3(-a.x)};
    };
    struct Case {
      glm::dvec3 axis;
      double degrees;
      glm::dvec3 from, to;
    };
    const double h = 0.5, r3 = std::sqrt(3.0) / 2.0;
    const Case cases[] = {
        // About -Z by +90 degrees is about +Z by -90: +X goes to -Y, +Y to +X.
        {{0, 0, -1}, 90, {1, 0, 0}, {0, -1, 0}},
        {{0, 0, -1}, 90, {0, 1, 0}, {1, 0, 0}},
        {{0, 0, -1}, 30, {1, 0, 0}, {r3, -h, 0}},
        {{0, 0, -1}, -90, {1, 0, 0}, {0, 1, 0}},
        // About -Y by +90 is about +Y by -90: +X goes to +Z, +Z to -X.
        {{0, -1, 0}, 90, {1, 0, 0}, {0, 0, 1}},
        {{0, -1, 0}, 90, {0, 0, 1}, {-1, 0, 0}},
        // About -X by +90 is about +X by -90: +Y goes to -Z, +Z to +Y.
        {{-1, 0, 0}, 90, {0, 1, 0}, {0, 0, -1}},
        {{-1, 0, 0}, 90, {0, 0, 1}, {0, 1, 0}},
        // About -(1, 1, 1) by +120 is about (1, 1, 1) by -120: X -> Z -> Y -> X.
        {{-1, -1, -1}, 120, {1, 0, 0}, {0, 0, 1}},
        {{-1, -1, -1}, 120, {0, 0, 1}, {0, 1, 0}},
        // And the positive axes the other way, for contrast: about +Z by +90, +X goes to +Y.
        {{0, 0, 1}, 90, {1, 0, 0}, {0, 1, 0}},
        {{1, 1, 1}, 120, {1, 0, 0}, {0, 1, 0}},
    };
    for (const Case& c : cases) {
      const ShRgb turned = AxisRotation(c.axis, 1).Rotate(band1(c.from), c.degrees * kPi / 180.0);
      const ShRgb expected = band1(c.to);
      INFO("axis (" << c.axis.x << ", " << c.axis.y << ", " << c.axis.z << "), " << c.degrees << " degrees");
      for (int k = 0; k < 4; ++k)
        for (int ch = 0; ch < 3; ++ch) CHECK(std::abs(turned[k][ch] - expected[k][ch]) < kBandLimitedTolerance);
    }
  }
}
