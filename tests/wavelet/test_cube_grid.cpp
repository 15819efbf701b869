// The wavelet cube (wavelet/cube_grid.h) and coefficient selection (wavelet/selection.h).
#include <doctest/doctest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "wavelet/cube_grid.h"
#include "wavelet/selection.h"

namespace prt {
namespace {

/// Sums of 6 F^2 exact terms: rounding only.
constexpr double kSumRounding = 1e-10;
/// A 64 x 64 midpoint rule over one texel against the exact clamped cosine: the rule's error
/// at the horizon's kink, measured below 2e-4 of the texel's value.
constexpr double kMidpointRule = 1e-3;

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("cube grid: solid angles cover the sphere, and every texel's centre maps back to it") {
    for (int f : {1, 8, 32}) {
      const CubeGrid grid(f);
      double sum = 0.0;
      for (std::size_t t = 0; t < grid.texels(); ++t) {
        sum += grid.SolidAngle(t);
        CHECK(grid.TexelOf(grid.Direction(t)) == t);
      }
      CHECK(std::abs(sum - 4 * kPi) < kSumRounding);
    }
    // Texel t looks along its face's axis: the centre of face 2 (posy) at F = 2 is +Y's corner.
    const CubeGrid two(2);
    CHECK(glm::dot(two.Direction(2 * 4), glm::dvec3(0, 1, 0)) > 0.5);
    CHECK(glm::dot(two.Direction(0), glm::dvec3(1, 0, 0)) > 0.5);
    CHECK(glm::dot(two.Direction(5 * 4), glm::dvec3(0, 0, -1)) > 0.5);
  }

  TEST_CASE("cube grid: the clamped cosine per texel is exact: pi in all, the midpoint rule in each") {
    const CubeGrid grid(8);
    for (const glm::dvec3& raw : {glm::dvec3(0, 1, 0), glm::dvec3(0.3, -0.5, 0.8), glm::dvec3(1, 1, 1)}) {
      const glm::dvec3 n = glm::normalize(raw);
      double sum = 0.0;
      for (std::size_t t = 0; t < grid.texels(); ++t) sum += grid.ClampedCosine(t, n);
      CHECK(std::abs(sum - kPi) < kSumRounding);  // integral of max(0, n.w) over the sphere
      // Each texel against a fine midpoint rule of max(0, n.w).
      std::vector<glm::dvec3> dirs;
      std::vector<double> omega;
      grid.SubTexels(64, dirs, omega);
      for (std::size_t t = 0; t < grid.texels(); ++t) {
        double rule = 0.0;
        for (std::size_t k = t * 4096; k < (t + 1) * 4096; ++k) rule += omega[k] * std::max(0.0, glm::dot(n, dirs[k]));
        CHECK(std::abs(rule - grid.ClampedCosine(t, n)) <= kMidpointRule * grid.SolidAngle(t));
      }
    }
  }

  TEST_CASE("cube grid: sub-squares split each texel's solid angle exactly") {
    const CubeGrid grid(4);
    std::vector<glm::dvec3> dirs;
    std::vector<double> omega;
    grid.SubTexels(3, dirs, omega);
    for (std::size_t t = 0; t < grid.texels(); ++t) {
      double sum = 0.0;
      for (std::size_t k = t * 9; k < (t + 1) * 9; ++k) {
        sum += omega[k];
        CHECK(grid.TexelOf(dirs[k]) == t);
      }
      CHECK(std::abs(sum - grid.SolidAngle(t)) < 1e-14);
    }
  }

  TEST_CASE("selection: the largest by magnitude, or by magnitude times support area; zeros never") {
    constexpr int f = 4;  // 96 coefficients
    std::vector<double> c(6 * f * f, 0.0);
    c[0] = 0.05;           // face 0's scaling coefficient: kept first, however small
    c[15] = -0.9;          // a finest detail of face 0: support 2 x 2
    c[16 + 5] = 0.7;       // a finest detail of face 1 (row 1, col 1: level 0, support 4 x 4)
    c[40] = 1e-9;
    std::vector<std::uint32_t> kept;
    KeepLargest(c.data(), SelectionWeights(f, Selection::kMagnitude), 2, kept);
    CHECK(kept == std::vector<std::uint32_t>{0, 15});
    c[16 + 2] = 0.3;       // face 1, row 0, col 2: a level-1 detail, support 2 x 2
    KeepLargest(c.data(), SelectionWeights(f, Selection::kArea), 3, kept);
    CHECK(kept == std::vector<std::uint32_t>{0, 15, 21});  // 0.7 * 16 and 0.9 * 4 beat 0.3 * 4
    KeepLargest(c.data(), SelectionWeights(f, Selection::kArea), 2, kept);
    CHECK(kept == std::vector<std::uint32_t>{0, 21});  // 0.7 * 16 beats 0.9 * 4
    KeepLargest(c.data(), SelectionWeights(f, Selection::kMagnitude), 10, kept);
    CHECK(kept == std::vector<std::uint32_t>{0, 15, 18, 21, 40});  // every nonzero, in order
  }
}

}  // namespace prt
