// The lobes of material/lobe.h: zonal coefficients against direct integration, the sampling
// density against the lobe.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "core/constants.h"
#include "material/lobe.h"
#include "sh/quadrature.h"

using namespace prt;

TEST_SUITE_BEGIN("material");

namespace {

/// h_l = 2 pi integral h(mu) P_l(mu) dmu by composite Gauss–Legendre on [lo, 1] (the Legendre
/// polynomial evaluated by its explicit sum rather than the recurrence the code uses).
double BruteCoefficient(const Lobe& lobe, int l) {
  std::vector<double> x, w;
  GaussLegendre(64, x, w);
  const double lo = lobe.MinMu();
  const int pieces = 400;
  double sum = 0.0;
  for (int p = 0; p < pieces; ++p) {
    const double a = lo + (1.0 - lo) * p / pieces, b = lo + (1.0 - lo) * (p + 1) / pieces;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double mu = 0.5 * (a + b) + 0.5 * (b - a) * x[i];
      // Rodrigues' explicit sum: P_l(x) = 2^-l sum_k (-1)^k C(l,k) C(2l-2k,l) x^(l-2k).
      double pl = 0.0;
      for (int k = 0; k <= l / 2; ++k)
        pl += ((k % 2) ? -1.0 : 1.0) * std::exp(std::lgamma(l + 1.0) - std::lgamma(k + 1.0) - std::lgamma(l - k + 1.0) +
                                                std::lgamma(2.0 * l - 2 * k + 1) - std::lgamma(l + 1.0) -
                                                std::lgamma(l - 2.0 * k + 1)) *
              std::pow(mu, l - 2 * k);
      sum += 0.5 * (b - a) * w[i] * lobe.Value(mu) * pl / std::pow(2.0, l);
    }
  }
  return 2.0 * kPi * sum;
}

}  // namespace

TEST_CASE("Phong and raised-cosine zonal coefficients match direct integration") {
  // Tolerance: the brute force's Legendre sum loses digits to cancellation at l = 12, about 1e-9.
  constexpr double kTol = 1e-8;
  for (LobeKind kind : {LobeKind::kPhong, LobeKind::kRaisedCosine})
    for (int n : {1, 2, 7, 30}) {
      Lobe lobe{kind, n};
      const std::vector<double> h = lobe.ZonalCoefficients(12);
      for (int l = 0; l <= 12; ++l) {
        CAPTURE(lobe.Name());
        CAPTURE(l);
        CHECK(h[l] == doctest::Approx(BruteCoefficient(lobe, l)).epsilon(kTol).scale(1.0));
      }
    }
}

TEST_CASE("h_0 is the lobe's integral over the sphere, and the raised cosine stops at its degree") {
  // Phong is normalised against the cosine (integral h mu ds = 1), so its plain integral is
  // (N+2)/(N+1); the raised cosine is normalised to 1.
  for (int n : {1, 5, 1000})
    CHECK(Lobe{LobeKind::kPhong, n}.ZonalCoefficients(0)[0] == doctest::Approx((n + 2.0) / (n + 1.0)).epsilon(1e-14));
  const std::vector<double> h = Lobe{LobeKind::kRaisedCosine, 4}.ZonalCoefficients(8);
  CHECK(h[0] == doctest::Approx(1.0).epsilon(1e-13));
  CHECK(std::abs(h[4]) > 1e-3);
  for (int l = 5; l <= 8; ++l) CHECK(std::abs(h[l]) < 1e-14);
}

TEST_CASE("Phong's coefficients fall off like exp(-l^2 / (2N)) (the sqrt(N) rule)") {
  // h_l / h_0 at l = sqrt(N) is near exp(-1/2) for a sharp lobe; the rule is approximate
  // (0.45..0.75 covers N = 100..1000).
  for (int n : {100, 400, 1000}) {
    const int l = int(std::lround(std::sqrt(double(n))));
    const std::vector<double> h = Lobe{LobeKind::kPhong, n}.ZonalCoefficients(l);
    CAPTURE(n);
    CHECK(h[l] / h[0] > 0.45);
    CHECK(h[l] / h[0] < 0.75);
  }
}

TEST_CASE("a lobe's samples have the lobe's density: the mean of weight * g(mu) is integral h g") {
  // With g = mu^2: phong gives 2 pi (N+2)/(2 pi) / (N+3); raised cosine by the brute rule.
  // Tolerance: the midpoint rule in u with 200000 points has error ~1e-9 of these smooth means.
  for (LobeKind kind : {LobeKind::kPhong, LobeKind::kRaisedCosine})
    for (int n : {1, 10, 1000}) {
      Lobe lobe{kind, n};
      const int m = 200000;
      double mean = 0.0;
      for (int i = 0; i < m; ++i) {
        double weight = 0.0;
        const double mu = lobe.SampleMu((i + 0.5) / m, weight);
        CHECK_MESSAGE(mu >= lobe.MinMu(), lobe.Name());
        mean += weight * mu * mu / m;
      }
      double expected = 0.0;
      if (kind == LobeKind::kPhong) {
        expected = (n + 2.0) / (n + 3.0);
      } else {
        // integral h mu^2 ds = (h_0 + 2 h_2) / 3 (mu^2 = (P_0 + 2 P_2)/3).
        const std::vector<double> h = lobe.ZonalCoefficients(2);
        expected = (h[0] + 2.0 * h[2]) / 3.0;
      }
      CAPTURE(lobe.Name());
      CHECK(mean == doctest::Approx(expected).epsilon(1e-6));
    }
}

TEST_CASE("the share of a lobe's energy in bands 0..lmax grows to 1, all of it for a band-limited lobe") {
  for (int n : {1, 10, 100, 1000}) {
    const Lobe lobe{LobeKind::kPhong, n};
    double previous = 0.0;
    for (int lmax : {0, 1, 2, 4, 8, 16, 32, 64}) {
      const double share = LobeBandShare(lobe, lmax);
      CHECK(share >= previous);
      CHECK(share <= 1.0 + 1e-12);
      previous = share;
    }
    CHECK(previous > 0.98);  // measured: 0.985 for N = 1000 at lmax 64, more for broader lobes
  }
  // Sharper lobes keep less in few bands.
  CHECK(LobeBandShare(Lobe{LobeKind::kPhong, 1000}, 2) < LobeBandShare(Lobe{LobeKind::kPhong, 10}, 2));
  CHECK(LobeBandShare(Lobe{LobeKind::kRaisedCosine, 5}, 5) == doctest::Approx(1.0).epsilon(1e-13));
  CHECK(LobeBandShare(Lobe{LobeKind::kRaisedCosine, 5}, 4) < 1.0 - 1e-6);
}

TEST_SUITE_END();
