// --window auto (sh/dering.h) and the non-negative kernel it ends at (sh/nonnegative_kernel.h).
// Everything is checked against something the code does not compute itself: Legendre zeros in
// closed form, an independent scan of random directions, and the minimality of the strength.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/rng.h"
#include "sh/basis.h"
#include "sh/dering.h"
#include "sh/nonnegative_kernel.h"
#include "sh/zonal.h"
#include "tests/sh/sh_test_util.h"
#include "tests/test_support.h"

using namespace prt;

namespace {

using test::RandomDirection;

/// Lowest channel of the reconstruction over `n` random directions: a scan independent of the
/// grid-and-compass search under test.
double RandomScanLowest(const ShRgb& c, int n, std::uint64_t seed) {
  Pcg32 rng(seed, 1);
  std::vector<glm::dvec3> directions(n);
  for (auto& d : directions) d = RandomDirection(rng);
  return test::LowestOver(c, directions);
}

/// A sky-like light: a constant `floor` plus a sun of `sun` (the projection of a delta of that
/// energy, which rings as hard as any light can) in direction `s`. The sun is bluest and the
/// floor reddest, so blue, the last channel, rings most: a search that looked at red alone would
/// stop short.
ShRgb SunLight(int lmax, const glm::dvec3& s, double sun, double floor) {
  ShRgb c(CoeffCount(lmax), glm::dvec3(0.0));
  const std::vector<double> y = EvalBasis(lmax, glm::normalize(s));
  for (std::size_t k = 0; k < c.size(); ++k) c[k] = sun * y[k] * glm::dvec3(0.5, 0.8, 1.0);
  c[0] += floor * std::sqrt(4.0 * kPi) * glm::dvec3(1.0, 0.5, 0.3);
  return c;
}

}  // namespace

TEST_SUITE("sh") {
  TEST_CASE("non-negative kernel: never negative, w_0 = 1, w_1 = the largest Legendre zero") {
    // Rounding of a sum of up to 65 terms of size 1 against K(1).
    constexpr double kRounding = 1e-14;
    for (int lmax = 0; lmax <= kMaxAutoWindowLmax; ++lmax) {
      const std::vector<double> w = NonNegativeKernelWeights(lmax);
      REQUIRE(w.size() == std::size_t(lmax + 1));
      CHECK(w[0] == 1.0);
      CHECK(KernelMinimumRatio(w) > -kRounding);
      for (int l = 1; l <= lmax; ++l) CHECK(w[l] <= w[l - 1] + kRounding);  // a low-pass window
    }
    // Even lmax, largest zeros of Legendre polynomials in closed form: P_2: 1/sqrt(3); P_3: sqrt(3/5).
    CHECK(NonNegativeKernelWeights(2)[1] == doctest::Approx(1.0 / std::sqrt(3.0)).epsilon(1e-13));
    CHECK(NonNegativeKernelWeights(4)[1] == doctest::Approx(std::sqrt(0.6)).epsilon(1e-13));
    // Odd lmax, of the polynomials orthogonal for the weight 1 + x, solved by hand from its
    // moments: x - 1/3 (K = 1 + x, w_1 = 1/3) and x^2 - 0.4 x - 0.2 (w_1 = 0.2 + sqrt(0.24),
    // sharper than the power of the cosine ((1 + x)/2)^3, whose w_1 is 0.6).
    CHECK(NonNegativeKernelWeights(1)[1] == doctest::Approx(1.0 / 3.0).epsilon(1e-13));
    CHECK(NonNegativeKernelWeights(3)[1] == doctest::Approx(0.2 + std::sqrt(0.24)).epsilon(1e-13));
    // Sharper than Hann, whose kernel is not even non-negative, from lmax 8 on.
    CHECK(NonNegativeKernelWeights(8)[1] > 0.9);
  }

  TEST_CASE("--window auto: a light already non-negative is left alone") {
    ShRgb c = SunLight(6, {0.2, 0.9, 0.1}, 0.0, 1.0);  // constant
    c[ShIndex(1, 0)] = glm::dvec3(0.5);                  // a gentle gradient, 1 + 0.5 Y_10 > 0
    const AutoWindow a = ChooseAutoWindow(c);
    CHECK(a.t == 0.0);
    for (double w : a.weights) CHECK(w == 1.0);
    CHECK(a.min_after == a.min_before);
    CHECK(a.min_before > 0);
    CHECK(a.irradiance_cost == 0.0);
  }

  TEST_CASE("--window auto: non-negative everywhere and no stronger than needed, lmax 1 to 64, suns to 1e5") {
    Pcg32 rng(21, 4);
    // Scaled under a sanitizer (tests/README.md): lmax 64 left to the unsanitized run.
    const std::vector<int> lmaxes = test::kSanitized ? std::vector<int>{1, 2, 3, 4, 8, 16, 33}
                                                     : std::vector<int>{1, 2, 3, 4, 8, 16, 33, 64};
    for (int lmax : lmaxes) {
      for (double ratio : {30.0, 1e5}) {
        const double floor = 1.0, sun = ratio * 4.0 * kPi * floor;  // sun energy / sky energy = ratio
        ShRgb c = SunLight(lmax, RandomDirection(rng), sun, floor);
        const AutoWindow a = ChooseAutoWindow(c);
        INFO("lmax " << lmax << ", sun " << ratio << ": t " << a.t << ", before " << a.min_before << ", after "
                     << a.min_after);
        CHECK(a.min_before < 0);  // the case rings
        ShRgb windowed = c;
        ApplyWeights(a.weights, windowed);
        const int scan = lmax > 16 ? 4000 : 20000;
        CHECK(a.min_after >= 0);
        CHECK(RandomScanLowest(windowed, scan, 5) >= 0);
        // Minimal: 1% less strength leaves a negative direction.
        ShRgb weaker = c;
        std::vector<double> w(a.weights.size());
        const std::vector<double> k = NonNegativeKernelWeights(lmax);
        const double t = 0.99 * a.t;
        for (std::size_t l = 0; l < w.size(); ++l) w[l] = (1.0 - t) + t * k[l];
        ApplyWeights(w, weaker);
        CHECK(LowestRadiance(weaker) < 0);
      }
    }
  }

  TEST_CASE("--window auto: its irradiance cost is the Parseval sum of what it removes") {
    // A light of bands 0 and 1 only: the cost is |1 - w_1| A_1 |L_1| / sqrt(A_0^2 |L_0|^2 + A_1^2 |L_1|^2).
    ShRgb c(CoeffCount(1), glm::dvec3(0.0));
    c[0] = glm::dvec3(1.0);
    // 1.5 Y_10 against Y_00 = 1 dips below zero, yet is the projection of a non-negative light
    // (a delta's band 1 is sqrt(3) times its band 0; any mix of deltas' is less).
    c[ShIndex(1, 0)] = glm::dvec3(1.5);
    const AutoWindow a = ChooseAutoWindow(c);
    REQUIRE(a.t > 0);
    const double a0 = ClampedCosineBand(0), a1 = ClampedCosineBand(1);
    const double expected = (1.0 - a.weights[1]) * a1 * 1.5 / std::sqrt(a0 * a0 + a1 * a1 * 2.25);
    CHECK(a.irradiance_cost == doctest::Approx(expected).epsilon(1e-12));
    // And the window is the least: 1/sqrt(4pi) + w_1 1.5 sqrt(3/4pi) z >= 0 down to z = -1 needs
    // w_1 <= 1/(1.5 sqrt(3)); the margin of 1e-6 in strength moves w_1 by less than 1e-6.
    CHECK(a.weights[1] == doctest::Approx(1.0 / (1.5 * std::sqrt(3.0))).epsilon(1e-5));
    CHECK(a.weights[1] <= 1.0 / (1.5 * std::sqrt(3.0)));
    CHECK(a.min_after >= 0);
  }

  TEST_CASE("--window auto: a channel that is zero everywhere stays zero, the others are windowed") {
    ShRgb c = SunLight(8, {0, 0, 1}, 1000.0, 1.0);
    for (auto& v : c) v.y = 0.0;  // green: no light at all
    const AutoWindow a = ChooseAutoWindow(c);
    CHECK(a.t > 0);
    CHECK(a.min_after >= 0);
  }

  TEST_CASE("--window auto: an RGB light needs the strength of its worst channel, no more") {
    // Each channel alone (copied into all three) gives its own least strength; the RGB light's
    // must be their maximum. A search that read one channel would find the wrong one and lean
    // on the safety check, which overshoots.
    Pcg32 rng(23, 2);
    for (int lmax : {2, 8}) {
      const ShRgb c = SunLight(lmax, RandomDirection(rng), 3000.0, 1.0);
      double worst = 0.0;
      for (int ch = 0; ch < 3; ++ch) {
        ShRgb mono = c;
        for (auto& v : mono) v = glm::dvec3(v[ch]);
        worst = std::max(worst, ChooseAutoWindow(mono).t);
      }
      const AutoWindow a = ChooseAutoWindow(c);
      INFO("lmax " << lmax << ": rgb " << a.t << ", worst channel " << worst);
      CHECK(a.t == doctest::Approx(worst).epsilon(1e-5));
    }
  }
}
