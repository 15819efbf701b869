#include <doctest/doctest.h>

#include <cmath>

#include "core/constants.h"
#include "sh/basis.h"
#include "sh/quadrature.h"
#include "sh/zonal.h"

#include <glm/geometric.hpp>

using namespace prt;

namespace {
// A_l by its closed form against values from R&H 2001: both exact, rounding only.
constexpr double kClosedFormTolerance = 1e-14;
}  // namespace

TEST_SUITE("sh") {
  TEST_CASE("A_l of the clamped cosine: R&H 2001 values") {
    CHECK(ClampedCosineBand(0) == doctest::Approx(kPi).epsilon(kClosedFormTolerance));
    CHECK(ClampedCosineBand(1) == doctest::Approx(2 * kPi / 3).epsilon(kClosedFormTolerance));
    CHECK(ClampedCosineBand(2) == doctest::Approx(kPi / 4).epsilon(kClosedFormTolerance));
    CHECK(ClampedCosineBand(3) == 0.0);
    CHECK(ClampedCosineBand(4) == doctest::Approx(-kPi / 24).epsilon(kClosedFormTolerance));
    CHECK(ClampedCosineBand(6) == doctest::Approx(kPi / 64).epsilon(kClosedFormTolerance));
    CHECK(ClampedCosineZonalCoeff(0) == doctest::Approx(0.886227).epsilon(1e-6));
    CHECK(ClampedCosineZonalCoeff(1) == doctest::Approx(1.023327).epsilon(1e-6));
    CHECK(ClampedCosineZonalCoeff(2) == doctest::Approx(0.495416).epsilon(1e-6));
    // Large l stays finite and decays like l^(-5/2) ... never a NaN from factorials.
    CHECK(std::isfinite(ClampedCosineBand(200)));
    CHECK(std::abs(ClampedCosineBand(200)) < 1e-4);
  }

  TEST_CASE("A_l agrees with the projection of max(0, z) by exact-order quadrature") {
    // max(0, z) has a kink at z = 0, so use Gauss-Legendre on each hemisphere separately
    // (z in [0, 1]): the integrand z * P_l(z) is then a polynomial and the rule is exact.
    const int lmax = 10;
    std::vector<double> z, w;
    GaussLegendre(16, z, w);
    for (int l = 0; l <= lmax; ++l) {
      double integral = 0.0;  // 2 pi * int_0^1 z Y_l0(z) dz
      for (int i = 0; i < 16; ++i) {
        const double zz = 0.5 * (z[i] + 1.0);
        const auto y = EvalBasis(l, {std::sqrt(1 - zz * zz), 0.0, zz});
        integral += 0.5 * w[i] * zz * y[ShIndex(l, 0)];
      }
      integral *= 2 * kPi;
      CHECK(integral == doctest::Approx(ClampedCosineZonalCoeff(l)).epsilon(1e-13));
    }
  }

  TEST_CASE("unshadowed transfer reproduces the furnace: constant radiance c gives c") {
    // L = c has L00 = 2 sqrt(pi) c; outgoing radiance = L00 T00 = c for any normal.
    double t[9];
    UnshadowedTransfer(2, glm::normalize(glm::dvec3(0.3, -0.5, 0.8)), t);
    const double c = 2.5;
    CHECK(2.0 * std::sqrt(kPi) * c * t[0] == doctest::Approx(c).epsilon(1e-15));
  }
}
