#include <doctest/doctest.h>

#include <cmath>

#include "core/constants.h"
#include "env/procedural.h"
#include "precompute/light.h"
#include "sh/basis.h"
#include "sh/quadrature.h"

using namespace prt;

TEST_SUITE("env") {
  TEST_CASE("cap integrals of P_l match exact Gauss-Legendre quadrature on [cos a, 1]") {
    // P_l is a polynomial of degree l: 40 Gauss nodes integrate it exactly up to l = 79.
    constexpr double kTolerance = 1e-13;
    std::vector<double> z, w;
    GaussLegendre(40, z, w);
    for (double x : {0.999990, 0.99, 0.5, -0.3}) {
      const auto integral = CapLegendreIntegrals(30, x);
      for (int l = 0; l <= 30; ++l) {
        double q = 0.0;
        for (int i = 0; i < 40; ++i) {
          const double t = x + (1.0 - x) * 0.5 * (z[i] + 1.0);
          double p0 = 1.0, p1 = t, pl = (l == 0) ? 1.0 : t;
          for (int k = 2; k <= l; ++k) {
            pl = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
            p0 = p1;
            p1 = pl;
          }
          q += 0.5 * (1.0 - x) * w[i] * pl;
        }
        CHECK(std::abs(integral[l] - q) < kTolerance);
      }
    }
  }

  TEST_CASE("sky: the analytic sun disk agrees with a brute-force projection of the disk") {
    // Project the whole sky (smooth part + disk) by a dense Gauss grid through Radiance() and
    // compare with ProjectLight (Gauss rows + analytic disk). The disk edge is a discontinuity,
    // so the dense grid converges slowly: 1200 latitudes put ~2000 nodes on the 2-degree disk;
    // its error is a few 1e-3 of the disk's own coefficient.
    SkyParams p;
    p.radius = 4.0;
    const auto sky = MakeSky(p);
    const int lmax = 4;
    const ShRgb fast = ProjectLight(*sky, lmax);
    const SphereQuadrature q = GaussSphere(1200);
    std::vector<double> y(CoeffCount(lmax));
    ShRgb brute(CoeffCount(lmax), glm::dvec3(0.0));
    for (std::size_t i = 0; i < q.directions.size(); ++i) {
      EvalBasis(lmax, q.directions[i], y.data());
      const glm::dvec3 L = sky->Radiance(q.directions[i]) * q.weights[i];
      for (int k = 0; k < CoeffCount(lmax); ++k) brute[k] += y[k] * L;
    }
    constexpr double kBruteForceTolerance = 5e-3;  // of the coefficient's scale, see above
    for (int k = 0; k < CoeffCount(lmax); ++k)
      for (int c = 0; c < 3; ++c) CHECK(std::abs(fast[k][c] - brute[k][c]) < kBruteForceTolerance * fast[0][c]);
  }

  TEST_CASE("sky: sun direction and radiance") {
    SkyParams p;
    const glm::dvec3 s = SunDirection(p);
    CHECK(s.y == doctest::Approx(std::sin(40 * kPi / 180)));
    const auto sky = MakeSky(p);
    CHECK(sky->Radiance(s).x > 100.0);                    // inside the disk: HDR
    CHECK(sky->Radiance({0, 1, 0}).z > sky->Radiance({0, 1, 0}).x);  // blue zenith
    CHECK(sky->Radiance({0, -1, 0}).x < 0.5);             // dim ground
  }
}
