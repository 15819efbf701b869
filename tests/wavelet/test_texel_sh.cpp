// SH over the cube's texels (wavelet/texel_sh.h): a function given by its texel integrals, or by
// its texel means, goes to its own SH coefficients, and back.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "sh/basis.h"
#include "sh/coeffs.h"
#include "wavelet/cube_grid.h"
#include "wavelet/texel_sh.h"

namespace prt {

TEST_SUITE("wavelet") {
  TEST_CASE("texel sh: an SH function's texel integrals and means give back its coefficients") {
    // f = sum_j c_j Y_j with every coefficient of lmax 4 set: its texel integrals (sub-sampled
    // finely) projected, and its texel means taken as a light, must give c; Subtract of c must
    // leave little. A texel function is f averaged over texels of about 2.8 degrees (F 32),
    // which blurs band 4 a little (measured up to 1.4e-2 at F 16, a quarter of it at F 32);
    // 1e-2 of the largest coefficient (1) bounds it.
    constexpr double kQuadrature = 1e-2;
    constexpr int kLmax = 4;
    const CubeGrid grid(32);
    const TexelSh sh(grid, kLmax);
    const int n = CoeffCount(kLmax);
    std::vector<double> c(n);
    for (int j = 0; j < n; ++j) c[j] = std::cos(1.7 * j + 0.3);  // all different, within [-1, 1]
    std::vector<glm::dvec3> dirs;
    std::vector<double> omega;
    grid.SubTexels(4, dirs, omega);
    std::vector<double> integrals(grid.texels(), 0.0), means(grid.texels());
    std::vector<double> y(n);
    for (std::size_t k = 0; k < dirs.size(); ++k) {
      EvalBasis(kLmax, dirs[k], y.data());
      double f = 0.0;
      for (int j = 0; j < n; ++j) f += c[j] * y[j];
      integrals[k / 16] += omega[k] * f;
    }
    for (std::size_t t = 0; t < grid.texels(); ++t) means[t] = integrals[t] / grid.SolidAngle(t);
    std::vector<double> s(n), l(n);
    sh.Project(integrals.data(), s.data());
    sh.OfLight(means, l.data());
    for (int j = 0; j < n; ++j) {
      CAPTURE(j);
      CHECK(std::abs(s[j] - c[j]) < kQuadrature);
      CHECK(std::abs(l[j] - c[j]) < kQuadrature);
    }
    double before = 0.0, after = 0.0;
    for (double v : integrals) before = std::max(before, std::abs(v));
    sh.Subtract(c.data(), integrals.data());
    for (double v : integrals) after = std::max(after, std::abs(v));
    CHECK(after < kQuadrature * before);
  }
}

}  // namespace prt
