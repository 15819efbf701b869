#include "material/lobe.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "sh/quadrature.h"

namespace prt {
namespace {

/// P_0..P_lmax at x by the three-term recurrence.
void Legendre(int lmax, double x, double* p) {
  p[0] = 1.0;
  if (lmax >= 1) p[1] = x;
  for (int l = 2; l <= lmax; ++l) p[l] = ((2.0 * l - 1.0) * x * p[l - 1] - (l - 1.0) * p[l - 2]) / l;
}
}  // namespace

double Lobe::Value(double mu) const {
  const double n = exponent;
  if (kind == LobeKind::kPhong) return mu > 0.0 ? (n + 2.0) / (2.0 * kPi) * std::pow(mu, n) : 0.0;
  return (n + 1.0) / (4.0 * kPi) * std::pow(0.5 * (1.0 + std::max(-1.0, mu)), n);
}

double Lobe::SupportAngle() const {
  // h(mu)/h(1) = mu^N (phong) or ((1+mu)/2)^P: below 1e-18 when the power's base is below
  // 1e-18^(1/N).
  const double base = std::pow(1e-18, 1.0 / exponent);
  if (kind == LobeKind::kPhong) return std::acos(base);
  return std::acos(std::max(-1.0, 2.0 * base - 1.0));
}

double Lobe::Width() const {
  // cos^N(t) ~ exp(-N t^2 / 2): standard deviation 1/sqrt(N); ((1+cos t)/2)^P ~ exp(-P t^2 / 4).
  const double scale = kind == LobeKind::kPhong ? 1.0 / std::sqrt(double(exponent))
                                                : std::sqrt(2.0 / double(exponent));
  return std::min(scale, kPi / 2.0);
}

double Lobe::SampleMu(double u, double& weight) const {
  const double n = exponent;
  if (kind == LobeKind::kPhong) {
    weight = (n + 2.0) / (n + 1.0);
    return std::pow(1.0 - u, 1.0 / (n + 1.0));  // 1 - u in (0, 1]: mu > 0
  }
  weight = 1.0;
  return std::max(-1.0, 2.0 * std::pow(1.0 - u, 1.0 / (n + 1.0)) - 1.0);
}

std::vector<double> Lobe::ZonalCoefficients(int lmax) const {
  std::vector<double> h(lmax + 1, 0.0);
  const double n = exponent;
  if (kind == LobeKind::kPhong) {
    std::vector<double> integral(lmax + 1);
    integral[0] = 1.0 / (n + 1.0);
    if (lmax >= 1) integral[1] = 1.0 / (n + 2.0);
    for (int l = 2; l <= lmax; ++l) integral[l] = (n - l + 2.0) / (n + l + 1.0) * integral[l - 2];
    for (int l = 0; l <= lmax; ++l) h[l] = (n + 2.0) * integral[l];
    return h;
  }
  // Raised cosine: a polynomial of degree P + l in mu, exact with (P + lmax)/2 + 1 nodes.
  std::vector<double> x, w, p(lmax + 1);
  GaussLegendre((exponent + lmax) / 2 + 1, x, w);
  for (std::size_t i = 0; i < x.size(); ++i) {
    Legendre(lmax, x[i], p.data());
    const double f = 2.0 * kPi * w[i] * Value(x[i]);
    for (int l = 0; l <= lmax; ++l) h[l] += f * p[l];
  }
  return h;
}

double LobeBandShare(const Lobe& lobe, int lmax) {
  const int last = std::max(lmax, int(3.0 * std::sqrt(double(lobe.exponent))) + 20);
  const std::vector<double> h = lobe.ZonalCoefficients(last);
  double kept = 0.0, total = 0.0;
  for (int l = 0; l <= last; ++l) {
    const double e = (2.0 * l + 1.0) * h[l] * h[l];
    total += e;
    if (l <= lmax) kept += e;
  }
  return kept / total;
}

int LmaxForShare(const Lobe& lobe, double share, int max_lmax) {
  int lmax = 0;
  while (lmax < max_lmax && LobeBandShare(lobe, lmax) < share) ++lmax;
  return lmax;
}

std::string Lobe::Name() const {
  return (kind == LobeKind::kPhong ? "phong:" : "raised-cosine:") + std::to_string(exponent);
}

}  // namespace prt
