// Spreading a direction over the cube's texels (wavelet/texel_spread.h): the weights are the
// normalised tents of every texel that reaches the direction (none missed, however the cube's
// faces meet), they sum to 1, and they change continuously as the direction moves.
#include <doctest/doctest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/rng.h"
#include "sh/rotation.h"
#include "wavelet/texel_spread.h"

namespace prt {
namespace {

/// Random unit directions, the same every run.
glm::dvec3 RandomDirection(Pcg32& rng) {
  const double z = 2.0 * rng.NextDouble() - 1.0, phi = 2.0 * kPi * rng.NextDouble();
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("texel spread: the weights are every reaching texel's tent over their sum") {
    // Brute force over every texel, against the lists the spread reads: a texel whose tent
    // reaches a direction but is not listed would take a jump of light with it.
    for (int size : {2, 4, 8, 16}) {
      CAPTURE(size);
      const CubeGrid grid(size);
      const TexelSpread spread(grid);
      Pcg32 rng(3, static_cast<std::uint64_t>(size));
      double least_sum = 1e300;
      for (int i = 0; i < 4000; ++i) {
        const glm::dvec3 d = RandomDirection(rng);
        std::vector<double> tent(grid.texels());
        double sum = 0.0;
        for (std::size_t t = 0; t < grid.texels(); ++t) sum += tent[t] = spread.Tent(t, d);
        least_sum = std::min(least_sum, sum);
        std::uint32_t to[kMaxSpread];
        double w[kMaxSpread];
        const int n = spread.Spread(d, to, w);
        double total = 0.0;
        int reaching = 0;
        for (double k : tent) reaching += k > 0.0;
        CHECK(n == reaching);
        for (int j = 0; j < n; ++j) {
          CHECK(w[j] == doctest::Approx(tent[to[j]] / sum).epsilon(1e-12));
          total += w[j];
        }
        CHECK(total == doctest::Approx(1.0).epsilon(1e-12));
      }
      // Every direction is well inside some tent: the sum stays far from 0 (measured >= 0.6).
      CHECK(least_sum > 0.5);
    }
  }

  TEST_CASE("texel spread: a direction moving in small steps moves its weights in small steps") {
    // Great circles through face centres, across the seams, and through the cube's corners,
    // in steps of 1/200 of a texel: a texel's weight may change by at most a few times the step
    // over the tent's radius. Putting the light in the one texel the direction falls in would
    // change one weight by 1 at every texel edge.
    constexpr int kSize = 16;
    const CubeGrid grid(kSize);
    const TexelSpread spread(grid);
    const double texel = 2.0 / kSize * 0.88;  // the smallest texel's width, at the corners (radians)
    const double step = texel / 200.0;
    // Lipschitz bound of a normalised tent: |dk/dd| <= 1/r and the sum >= 0.5, so a weight moves by
    // at most about 4 step / r, r >= texel (tent radius 1 in units of the texel's width).
    const double bound = 8.0 * step / texel;
    const glm::dvec3 axes[] = {glm::normalize(glm::dvec3(0, 1, 0)), glm::normalize(glm::dvec3(1, 1, 1)),
                               glm::normalize(glm::dvec3(1, -1, 0.3)), glm::normalize(glm::dvec3(0.2, 0.1, 1))};
    for (const glm::dvec3& axis : axes) {
      // A start perpendicular to the axis.
      const glm::dvec3 start = glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
      std::vector<double> before(grid.texels(), 0.0), now(grid.texels());
      double worst = 0.0;
      const int steps = static_cast<int>(2.0 * kPi / step);
      for (int i = 0; i <= steps; ++i) {
        std::fill(now.begin(), now.end(), 0.0);
        std::uint32_t to[kMaxSpread];
        double w[kMaxSpread];
        const int n = spread.Spread(AxisAngle(axis, i * step) * start, to, w);
        for (int j = 0; j < n; ++j) now[to[j]] = w[j];
        if (i > 0)
          for (std::size_t t = 0; t < grid.texels(); ++t) worst = std::max(worst, std::abs(now[t] - before[t]));
        before.swap(now);
      }
      CHECK(worst < bound);
    }
  }
}

}  // namespace prt
