// The Haar transform (wavelet/haar.h): orthonormal, exact round trip, Parseval, and the values
// and layout the header promises (the signs of a step, the scaling coefficient of every level).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/rng.h"
#include "wavelet/haar.h"
#include "wavelet/selection.h"

namespace prt {
namespace {

/// Rounding of a transform of a few hundred additions of O(1) values.
constexpr double kRounding = 1e-12;

std::vector<double> Random(int n, std::uint64_t seed) {
  Pcg32 rng(seed, 7);
  std::vector<double> x(static_cast<std::size_t>(n) * n);
  for (double& v : x) v = rng.NextDouble() * 2.0 - 1.0;
  return x;
}

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("haar: one step's values and signs on a 2 x 2 image") {
    // [a b; c d] -> rows, then columns, each (x + y)/sqrt2, (x - y)/sqrt2:
    // [(a+b+c+d)/2, (a-b+c-d)/2; (a+b-c-d)/2, (a-b-c+d)/2].
    std::vector<double> x = {1.0, 2.0, 3.0, 5.0}, scratch;
    HaarForward(x.data(), 2, scratch);
    CHECK(x[0] == doctest::Approx(11.0 / 2).epsilon(kRounding));
    CHECK(x[1] == doctest::Approx(-3.0 / 2).epsilon(kRounding));
    CHECK(x[2] == doctest::Approx(-5.0 / 2).epsilon(kRounding));
    CHECK(x[3] == doctest::Approx(1.0 / 2).epsilon(kRounding));
  }

  TEST_CASE("haar: a constant image is its scaling coefficient alone, at every size") {
    for (int n : {1, 2, 4, 8, 32}) {
      std::vector<double> x(static_cast<std::size_t>(n) * n, 0.75), scratch;
      HaarForward(x.data(), n, scratch);
      // The sum over the image over n (orthonormal: the scaling function is 1/n everywhere).
      CHECK(std::abs(x[0] - 0.75 * n) < kRounding * n);
      for (std::size_t i = 1; i < x.size(); ++i) CHECK(std::abs(x[i]) < kRounding * n);
    }
  }

  TEST_CASE("haar: the round trip is exact to rounding") {
    for (int n : {2, 8, 64}) {
      const std::vector<double> x = Random(n, n);
      std::vector<double> y = x, scratch;
      HaarForward(y.data(), n, scratch);
      HaarInverse(y.data(), n, scratch);
      for (std::size_t i = 0; i < x.size(); ++i) CHECK(std::abs(y[i] - x[i]) < kRounding);
    }
  }

  TEST_CASE("haar: the basis is orthonormal (8 x 8: every pair of basis images)") {
    // Basis image k is the inverse transform of the unit coefficient vector e_k.
    constexpr int n = 8;
    std::vector<std::vector<double>> basis(n * n, std::vector<double>(n * n, 0.0));
    std::vector<double> scratch;
    for (int k = 0; k < n * n; ++k) {
      basis[k][k] = 1.0;
      HaarInverse(basis[k].data(), n, scratch);
    }
    double worst = 0.0;
    for (int a = 0; a < n * n; ++a)
      for (int b = 0; b < n * n; ++b) {
        double dot = 0.0;
        for (int i = 0; i < n * n; ++i) dot += basis[a][i] * basis[b][i];
        worst = std::max(worst, std::abs(dot - (a == b ? 1.0 : 0.0)));
      }
    CHECK(worst < kRounding);
  }

  TEST_CASE("haar: Parseval: norms and inner products are the same in either basis") {
    constexpr int n = 32;
    std::vector<double> x = Random(n, 1), y = Random(n, 2), scratch;
    double xx = 0, xy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) xx += x[i] * x[i], xy += x[i] * y[i];
    HaarForward(x.data(), n, scratch);
    HaarForward(y.data(), n, scratch);
    double cc = 0, cd = 0;
    for (std::size_t i = 0; i < x.size(); ++i) cc += x[i] * x[i], cd += x[i] * y[i];
    CHECK(std::abs(cc - xx) < 1e-10 * xx);
    CHECK(std::abs(cd - xy) < 1e-10 * std::abs(xx));
  }

  TEST_CASE("haar: a detail covers the square its level says") {
    // A point at texel (5, 2) of a 16 x 16 image touches exactly one detail of each orientation
    // per level (and the scaling coefficient): 3 * 4 + 1 nonzero coefficients.
    constexpr int n = 16;
    std::vector<double> x(n * n, 0.0), scratch;
    x[5 * n + 2] = 1.0;
    HaarForward(x.data(), n, scratch);
    int nonzero = 0;
    for (double v : x) nonzero += std::abs(v) > kRounding;
    CHECK(nonzero == 13);
    CHECK(HaarSupport(0, 0, n) == 16);
    CHECK(HaarSupport(0, 1, n) == 16);
    CHECK(HaarSupport(1, 1, n) == 16);
    CHECK(HaarSupport(3, 2, n) == 8);
    CHECK(HaarSupport(15, 0, n) == 2);
    CHECK(HaarSupport(8, 8, n) == 2);
  }

  TEST_CASE("selection: area weights are each detail's support in texels, as the inverse transform spreads it") {
    // The documented rule, by an independent route: a coefficient's support area is the number
    // of texels the inverse transform of that coefficient alone touches; each face's scaling
    // coefficient is kept first (weight infinity) under either rule.
    constexpr int n = 8;
    const std::size_t face = std::size_t(n) * n;
    const std::vector<double> area = SelectionWeights(n, Selection::kArea);
    const std::vector<double> magnitude = SelectionWeights(n, Selection::kMagnitude);
    REQUIRE(area.size() == 6 * face);
    REQUIRE(magnitude.size() == 6 * face);
    std::vector<double> scratch;
    for (std::size_t i = 0; i < 6 * face; ++i) {
      CAPTURE(i);
      if (i % face == 0) {
        CHECK(area[i] == std::numeric_limits<double>::infinity());
        CHECK(magnitude[i] == std::numeric_limits<double>::infinity());
        continue;
      }
      std::vector<double> x(face, 0.0);
      x[i % face] = 1.0;
      HaarInverse(x.data(), n, scratch);
      const double touched = double(std::count_if(x.begin(), x.end(), [](double v) { return std::abs(v) > kRounding; }));
      CHECK(area[i] == touched);
      CHECK(magnitude[i] == 1.0);
    }
    // The kept ones: the scaling coefficients, then the largest |c| x area, by brute force.
    std::vector<double> c = Random(n, 9);
    for (int f = 1; f < 6; ++f) {
      const std::vector<double> more = Random(n, 9 + f);
      c.insert(c.end(), more.begin(), more.end());
    }
    constexpr std::size_t kBudget = 40;
    std::vector<std::uint32_t> kept;
    KeepLargest(c.data(), area, kBudget, kept);
    std::vector<std::uint32_t> order(c.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      const double wa = a % face == 0 ? 1e300 : std::abs(c[a]) * area[a], wb = b % face == 0 ? 1e300 : std::abs(c[b]) * area[b];
      return wa > wb || (wa == wb && a < b);
    });
    std::vector<std::uint32_t> expected(order.begin(), order.begin() + kBudget);
    std::sort(expected.begin(), expected.end());
    CHECK(kept == expected);
  }
}

}  // namespace prt
