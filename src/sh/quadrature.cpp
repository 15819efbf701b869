#include "sh/quadrature.h"
#include "core/constants.h"

#include <cmath>

namespace prt {

void GaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int iter = 0; iter < 100; ++iter) {
      // P_n(z) and its derivative by the three-term recurrence.
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = (n == 1) ? z : p1, pn1 = (n == 1) ? 1.0 : p0;
      dp = n * (z * pn - pn1) / (z * z - 1.0);
      const double dz = pn / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    const double w = 2.0 / ((1.0 - z * z) * dp * dp);
    nodes[i] = -z;
    nodes[n - 1 - i] = z;
    weights[i] = weights[n - 1 - i] = w;
  }
}

SphereQuadrature GaussSphere(int n) {
  std::vector<double> z, w;
  GaussLegendre(n, z, w);
  SphereQuadrature q;
  const int nphi = 2 * n;
  for (int i = 0; i < n; ++i) {
    const double s = std::sqrt((1.0 - z[i]) * (1.0 + z[i]));
    for (int j = 0; j < nphi; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / nphi;
      q.directions.push_back({s * std::cos(phi), s * std::sin(phi), z[i]});
      q.weights.push_back(w[i] * 2.0 * kPi / nphi);
    }
  }
  return q;
}

}  // namespace prt
