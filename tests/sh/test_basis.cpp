#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "core/constants.h"
#include "core/rng.h"
#include "sh/basis.h"
#include "sh/quadrature.h"
#include "tests/sh/sh_test_util.h"

using namespace prt;

namespace {

using test::RandomDirection;

// The basis promise: at most 1e-12 from the long-double reference for lmax <= 64.
constexpr double kReferenceTolerance = 1e-12;
// Closed forms and recurrence are two double evaluations of the same polynomials: a few ulps.
constexpr double kClosedFormTolerance = 1e-15;
// Two summation orders of 259 terms, each basis value within 1e-12 of the reference: rounding
// of the sum is far below this share of the sum of the terms' magnitudes.
constexpr double kBatchSumTolerance = 1e-11;
// Gauss quadrature is exact for these polynomials; what remains is rounding over ~10^4 terms.
constexpr double kOrthonormalityTolerance = 1e-12;

}  // namespace

TEST_SUITE("sh") {
  TEST_CASE("coefficient indexing") {
    CHECK(CoeffCount(0) == 1);
    CHECK(CoeffCount(2) == 9);
    CHECK(ShIndex(2, -2) == 4);
    CHECK(ShIndex(2, 2) == 8);
    CHECK(LmaxOfCount(9) == 2);
    CHECK(LmaxOfCount(10) == -1);
    CHECK(LmaxOfCount(0) == -1);
  }

  TEST_CASE("closed forms of bands 0..2 agree with the recurrence") {
    Pcg32 rng(7, 0);
    for (int i = 0; i < 1000; ++i) {
      const glm::dvec3 d = RandomDirection(rng);
      double a[9], b[9];
      EvalBasisBand2(d, a);
      EvalBasisRecurrence(2, d, b);
      for (int k = 0; k < 9; ++k) REQUIRE(std::abs(a[k] - b[k]) < kClosedFormTolerance);
    }
  }

  TEST_CASE("signs follow the Condon-Shortley convention of CONVENTIONS.md") {
    const auto x = EvalBasis(2, {1, 0, 0});
    const auto y = EvalBasis(2, {0, 1, 0});
    const auto z = EvalBasis(2, {0, 0, 1});
    CHECK(y[1] == doctest::Approx(-0.488603).epsilon(1e-6));  // Y1-1 = -c y
    CHECK(z[2] == doctest::Approx(0.488603).epsilon(1e-6));   // Y10 = c z
    CHECK(x[3] == doctest::Approx(-0.488603).epsilon(1e-6));  // Y11 = -c x
    CHECK(z[6] == doctest::Approx(0.630783).epsilon(1e-6));   // Y20 = 0.315392 (3 - 1)
    CHECK(x[8] == doctest::Approx(0.546274).epsilon(1e-6));
  }

  TEST_CASE("recurrence matches the long-double reference to 1e-12 up to lmax 64") {
    const int lmax = 64;
    Pcg32 rng(11, 0);
    std::vector<glm::dvec3> dirs = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 60; ++i) dirs.push_back(RandomDirection(rng));
    const double zn = 1.0 - 1e-9;  // near the pole
    dirs.push_back({std::sqrt((1 - zn) * (1 + zn)), 0.0, zn});
    std::vector<double> y(CoeffCount(lmax));
    double worst = 0.0;
    for (const auto& d : dirs) {
      EvalBasis(lmax, d, y.data());
      for (int l = 0; l <= lmax; ++l)
        for (int m = -l; m <= l; ++m) {
          const double ref = static_cast<double>(EvalBasisReference(l, m, d));
          worst = std::max(worst, std::abs(y[ShIndex(l, m)] - ref));
        }
    }
    MESSAGE("worst |Y - reference| up to lmax 64: " << worst);
    CHECK(worst < kReferenceTolerance);
  }

  TEST_CASE("finite to lmax 200 at every direction, exact poles included") {
    const int lmax = kMaxBasisLmax;
    std::vector<double> y(CoeffCount(lmax));
    const double zn = 1.0 - 1e-15;
    std::vector<glm::dvec3> dirs = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0},
                                    {std::sqrt((1 - zn) * (1 + zn)), 0, zn},
                                    {0, std::sqrt((1 - zn) * (1 + zn)), -zn}};
    Pcg32 rng(3, 0);
    for (int i = 0; i < 20; ++i) dirs.push_back(RandomDirection(rng));
    for (const auto& d : dirs) {
      EvalBasis(lmax, d, y.data());
      bool finite = true;
      for (double v : y) finite &= std::isfinite(v);
      CHECK(finite);
    }
    // At the north pole only m = 0 survives, with the value sqrt((2l+1)/(4 pi)).
    EvalBasis(lmax, {0, 0, 1}, y.data());
    CHECK(y[ShIndex(200, 0)] == doctest::Approx(std::sqrt(401.0 / (4 * kPi))).epsilon(1e-12));
    CHECK(y[ShIndex(200, 7)] == 0.0);
  }

  TEST_CASE("orthonormal by exact Gauss quadrature (lmax 12)") {
    const int lmax = 12;
    const int n = CoeffCount(lmax);
    const SphereQuadrature q = GaussSphere(lmax + 1);
    std::vector<double> gram(n * n, 0.0), y(n);
    for (std::size_t s = 0; s < q.directions.size(); ++s) {
      EvalBasis(lmax, q.directions[s], y.data());
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) gram[i * n + j] += q.weights[s] * y[i] * y[j];
    }
    double worst = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) worst = std::max(worst, std::abs(gram[i * n + j] - (i == j ? 1.0 : 0.0)));
    CHECK(worst < kOrthonormalityTolerance);
  }

  TEST_CASE("Gauss-Legendre weights sum to 2 and integrate z^(2n-1) exactly") {
    std::vector<double> z, w;
    GaussLegendre(20, z, w);
    double sw = 0, s38 = 0;
    for (int i = 0; i < 20; ++i) {
      sw += w[i];
      s38 += w[i] * std::pow(z[i], 38);
    }
    CHECK(sw == doctest::Approx(2.0).epsilon(1e-14));
    CHECK(s38 == doctest::Approx(2.0 / 39.0).epsilon(1e-13));
  }
}

TEST_SUITE("sh") {
  TEST_CASE("batch projection: every kernel gives the same bits, and the plain sum of EvalBasis") {
    // n = 259 directions (not a multiple of any vector width) with weights per channel, at
    // lmax 2 (closed forms elsewhere), 8 and 17. Each kernel this CPU runs must agree with the
    // baseline bit for bit (the sum order is fixed), and all with a plain double loop.
    Pcg32 rng(21, 4);
    const std::size_t n = 259;
    std::vector<double> x(n), y(n), z(n), w[3];
    for (auto& c : w) c.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3 d = RandomDirection(rng);
      x[i] = d.x, y[i] = d.y, z[i] = d.z;
      for (auto& c : w) c[i] = rng.NextDouble() - 0.25;
    }
    for (int lmax : {2, 8, 17}) {
      const std::size_t count = CoeffCount(lmax);
      std::vector<double> plain(3 * count, 0.0), magnitude(3 * count, 0.0), basis(count);
      for (std::size_t i = 0; i < n; ++i) {
        EvalBasisRecurrence(lmax, glm::dvec3(x[i], y[i], z[i]), basis.data());
        for (int c = 0; c < 3; ++c)
          for (std::size_t k = 0; k < count; ++k) {
            plain[c * count + k] += basis[k] * w[c][i];
            magnitude[c * count + k] += std::fabs(basis[k] * w[c][i]);
          }
      }
      std::vector<double> baseline(3 * count, 0.0);
      ProjectBasisBatchAt(VectorLevel::kBaseline, lmax, n, x.data(), y.data(), z.data(), w[0].data(), w[1].data(),
                          w[2].data(), baseline.data());
      for (std::size_t k = 0; k < 3 * count; ++k)
        REQUIRE(std::fabs(baseline[k] - plain[k]) <= kBatchSumTolerance * magnitude[k]);
      for (VectorLevel level : {VectorLevel::kAvx2, VectorLevel::kX86_64V4}) {
        std::vector<double> wide(3 * count, 0.0);
        ProjectBasisBatchAt(level, lmax, n, x.data(), y.data(), z.data(), w[0].data(), w[1].data(), w[2].data(),
                            wide.data());
        CHECK(wide == baseline);
      }
    }
  }

  TEST_CASE("batch evaluation: every kernel gives the same bits, each direction EvalBasis's values") {
    // n from 1 to 37 directions (every remainder of the vector groups and the padded last one),
    // at lmax 2, 4 and 9: each kernel this CPU runs writes what the baseline writes, and every
    // value is the recurrence's within a few ulps of the largest basis value of its band.
    constexpr double kRoundingTolerance = 1e-13;  // ulps of values up to ~1 (EvalBasis rounds in another order)
    Pcg32 rng(5, 8);
    for (std::size_t n : {std::size_t(1), std::size_t(2), std::size_t(3), std::size_t(7), std::size_t(16), std::size_t(37)}) {
      std::vector<double> x(n), y(n), z(n);
      for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 d = RandomDirection(rng);
        x[i] = d.x, y[i] = d.y, z[i] = d.z;
      }
      for (int lmax : {2, 4, 9}) {
        const std::size_t count = CoeffCount(lmax);
        std::vector<double> baseline(n * count, -7.0), basis(count);
        EvalBasisBatchAt(VectorLevel::kBaseline, lmax, n, x.data(), y.data(), z.data(), baseline.data());
        for (std::size_t i = 0; i < n; ++i) {
          EvalBasisRecurrence(lmax, glm::dvec3(x[i], y[i], z[i]), basis.data());
          for (std::size_t k = 0; k < count; ++k)
            REQUIRE(std::fabs(baseline[i * count + k] - basis[k]) <= kRoundingTolerance);
        }
        for (VectorLevel level : {VectorLevel::kAvx2, VectorLevel::kX86_64V4}) {
          std::vector<double> wide(n * count, 7.0);
          EvalBasisBatchAt(level, lmax, n, x.data(), y.data(), z.data(), wide.data());
          CHECK(wide == baseline);
        }
      }
    }
  }
}
