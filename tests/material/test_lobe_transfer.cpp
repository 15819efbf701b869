// The unshadowed lobe transfer (material/lobe_transfer.h) against a brute-force integration in
// a different frame (about the normal, where the clamped cosine is exact and the lobe is what
// varies), and the white-furnace values in closed form.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "material/lobe_transfer.h"
#include "sh/basis.h"
#include "sh/coeffs.h"
#include "sh/quadrature.h"

using namespace prt;

TEST_SUITE_BEGIN("material");

namespace {

/// t_k by brute force about n: z = n.s by composite Gauss–Legendre on [0, 1] (exact in the
/// clamped cosine), phi about n by `azimuths` equally spaced points.
std::vector<double> BruteTransfer(const Lobe& lobe, const glm::dvec3& n, const glm::dvec3& r, int lmax, int pieces,
                                  int azimuths) {
  std::vector<double> x, w;
  GaussLegendre(16, x, w);
  const glm::dvec3 a = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(n, a)), e2 = glm::cross(n, e1);
  std::vector<double> t(CoeffCount(lmax), 0.0), y(t.size());
  for (int p = 0; p < pieces; ++p) {
    const double lo = double(p) / pieces, hi = double(p + 1) / pieces;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double z = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x[i];
      const double wz = 0.5 * (hi - lo) * w[i], rho = std::sqrt(1.0 - z * z);
      for (int j = 0; j < azimuths; ++j) {
        const double phi = 2.0 * kPi * (j + 0.5) / azimuths;
        const glm::dvec3 s = z * n + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
        const double h = lobe.Value(glm::dot(r, s));
        if (h == 0.0) continue;
        EvalBasis(lmax, s, y.data());
        const double f = wz * (2.0 * kPi / azimuths) * h * z;
        for (std::size_t k = 0; k < t.size(); ++k) t[k] += f * y[k];
      }
    }
  }
  return t;
}

glm::dvec3 ViewAt(double degrees) {  // n = +Z, the view tilted toward +X
  const double a = degrees * kPi / 180.0;
  return {std::sin(a), 0.0, std::cos(a)};
}

}  // namespace

TEST_CASE("lobe transfer matches brute-force integration about the normal at every view angle") {
  // Tolerance: the brute force's azimuth sum converges like the lobe's kink at r.s = 0 (order N);
  // with these resolutions its own error is below 2e-7 of the largest coefficient.
  constexpr double kTol = 2e-7;
  const int lmax = 4;
  const glm::dvec3 n(0, 0, 1);
  for (LobeKind kind : {LobeKind::kPhong, LobeKind::kRaisedCosine})
    for (int exponent : {3, 40})
      for (double view : {0.0, 30.0, 70.0, 89.0, 120.0}) {
        const Lobe lobe{kind, exponent};
        const glm::dvec3 r = MirrorView(n, ViewAt(view));
        std::vector<double> t(CoeffCount(lmax));
        LobeTransfer(lobe, n, r, lmax, t.data());
        const std::vector<double> brute = BruteTransfer(lobe, n, r, lmax, 64, 720);
        double peak = 0.0;
        for (double b : brute) peak = std::max(peak, std::abs(b));
        CAPTURE(lobe.Name());
        CAPTURE(view);
        for (std::size_t k = 0; k < t.size(); ++k) CHECK(std::abs(t[k] - brute[k]) <= kTol * std::max(peak, 1e-3));
      }
}

TEST_CASE("white furnace through the lobe: exactly 1 at normal view, the closed form of N = 1 at any view") {
  const glm::dvec3 n(0, 0, 1);
  for (int exponent : {1, 2, 10, 100, 1000})
    CHECK(LobeCosineIntegral(Lobe{LobeKind::kPhong, exponent}, n, n) == doctest::Approx(1.0).epsilon(1e-10));
  // N = 1: (3 / 2 pi) integral max(0, r.s) max(0, n.s) ds with g the angle between r and n is
  // (3 / 2 pi) (2/3) ((pi - g) cos g + sin g) / 2 ... written as (sin g + (pi - g) cos g) / pi.
  for (double g_deg : {0.0, 20.0, 60.0, 90.0, 140.0}) {
    const double g = g_deg * kPi / 180.0;
    const glm::dvec3 r(std::sin(g), 0.0, std::cos(g));
    const double expected = (std::sin(g) + (kPi - g) * std::cos(g)) / kPi;
    CAPTURE(g_deg);
    CHECK(LobeCosineIntegral(Lobe{LobeKind::kPhong, 1}, n, r) == doctest::Approx(expected).epsilon(1e-10));
  }
}

TEST_CASE("a sharp lobe (N = 1000) keeps its furnace value as the view tilts until the horizon cuts it") {
  // Away from the horizon the lobe sees n.s = cos(g) to first order: integral ~ cos(g) over the
  // lobe's mean; at 89 degrees half the lobe is below the horizon.
  const glm::dvec3 n(0, 0, 1);
  const Lobe lobe{LobeKind::kPhong, 1000};
  for (double view : {10.0, 45.0, 80.0}) {
    const glm::dvec3 r = MirrorView(n, ViewAt(view));
    const double expected = std::cos(view * kPi / 180.0);
    CAPTURE(view);
    CHECK(LobeCosineIntegral(lobe, n, r) == doctest::Approx(expected).epsilon(3e-3));
  }
}

TEST_CASE("the lobe transfer table agrees with the direct rule at random normals and axes") {
  // Tolerance: cubic interpolation on 32 nodes per lobe width, measured up to 1.2e-7 of the
  // largest coefficient (lmax 2 and 8, N = 1..1000).
  constexpr double kTol = 3e-7;
  const int lmax = 4;
  std::uint64_t state = 12345;
  auto uniform = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / 9007199254740992.0;
  };
  auto direction = [&] {
    const double z = 2.0 * uniform() - 1.0, phi = 2.0 * kPi * uniform(), s = std::sqrt(1.0 - z * z);
    return glm::dvec3(s * std::cos(phi), s * std::sin(phi), z);
  };
  for (int exponent : {1, 20, 1000}) {
    const Lobe lobe{LobeKind::kPhong, exponent};
    const LobeTransferTable table(lobe, lmax);
    for (int i = 0; i < 40; ++i) {
      const glm::dvec3 n = direction(), r = direction();
      std::vector<double> a(CoeffCount(lmax)), b(a.size());
      table.Transfer(n, r, a.data());
      LobeTransfer(lobe, n, r, lmax, b.data());
      double peak = 0.0;
      for (double x : b) peak = std::max(peak, std::abs(x));
      CAPTURE(exponent);
      for (std::size_t k = 0; k < a.size(); ++k) CHECK(std::abs(a[k] - b[k]) <= kTol * std::max(peak, 1e-3));
    }
  }
}

TEST_SUITE_END();
