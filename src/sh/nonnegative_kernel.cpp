#include "sh/nonnegative_kernel.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "sh/quadrature.h"

namespace prt {
namespace {

/// P_0(x) .. P_n(x) by the three-term recurrence.
std::vector<double> Legendre(int n, double x) {
  std::vector<double> p(n + 1);
  p[0] = 1.0;
  if (n >= 1) p[1] = x;
  for (int l = 1; l < n; ++l) p[l + 1] = ((2.0 * l + 1.0) * x * p[l] - l * p[l - 1]) / (l + 1.0);
  return p;
}

/// The polynomials q_0..q_{n+1} orthonormal for the weight omega, as their recurrence
/// b_{k+1} q_{k+1} = (x - a_k) q_k - b_k q_{k-1}, q_0 = 1 / sqrt(int omega).
struct Orthonormal {
  std::vector<double> a, b;  ///< a_0..a_n, b_0..b_{n+1} (b_0 = 0)
  double q0 = 0;

  /// q_0(x)..q_{n+1}(x), and the derivative of q_{n+1}.
  std::vector<double> At(double x, double* derivative = nullptr) const {
    const int n = static_cast<int>(a.size()) - 1;
    std::vector<double> q(n + 2), dq(n + 2, 0.0);
    q[0] = q0;
    for (int k = 0; k <= n; ++k) {
      const double prev = k > 0 ? q[k - 1] : 0.0, dprev = k > 0 ? dq[k - 1] : 0.0;
      q[k + 1] = ((x - a[k]) * q[k] - b[k] * prev) / b[k + 1];
      dq[k + 1] = (q[k] + (x - a[k]) * dq[k] - b[k] * dprev) / b[k + 1];
    }
    if (derivative) *derivative = dq[n + 1];
    return q;
  }
};

/// Stieltjes' procedure: the recurrence of degrees 0..n+1 from the discrete inner product
/// sum_i w_i omega_i f(x_i) g(x_i), exact for the degrees used (deg <= 2n + 3 + odd).
Orthonormal Stieltjes(int n, const std::vector<double>& x, const std::vector<double>& w) {
  Orthonormal r;
  r.a.assign(n + 1, 0.0);
  r.b.assign(n + 2, 0.0);
  double mass = 0.0;
  for (double v : w) mass += v;
  r.q0 = 1.0 / std::sqrt(mass);
  std::vector<double> prev(x.size(), 0.0), cur(x.size(), r.q0), next(x.size());
  for (int k = 0; k <= n; ++k) {
    for (std::size_t i = 0; i < x.size(); ++i) r.a[k] += w[i] * x[i] * cur[i] * cur[i];
    double norm = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      next[i] = (x[i] - r.a[k]) * cur[i] - r.b[k] * prev[i];
      norm += w[i] * next[i] * next[i];
    }
    r.b[k + 1] = std::sqrt(norm);
    for (std::size_t i = 0; i < x.size(); ++i) next[i] /= r.b[k + 1];
    std::swap(prev, cur);
    std::swap(cur, next);
  }
  return r;
}

}  // namespace

std::vector<double> NonNegativeKernelWeights(int lmax) {
  const int n = lmax / 2;
  const bool odd = lmax % 2 == 1;
  std::vector<double> nodes, weights;
  GaussLegendre(lmax + 2, nodes, weights);  // exact to degree 2 lmax + 3
  std::vector<double> omega_w(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) omega_w[i] = weights[i] * (odd ? 1.0 + nodes[i] : 1.0);
  const Orthonormal q = Stieltjes(n, nodes, omega_w);

  double x = 1.0;  // above every zero: Newton falls monotonically onto the largest
  for (int it = 0; it < 200; ++it) {
    double slope = 0.0;
    const double value = q.At(x, &slope)[n + 1];
    const double step = value / slope;
    x -= step;
    if (!(std::abs(step) > 1e-16)) break;
  }
  const std::vector<double> at_zero = q.At(x);

  std::vector<double> w(lmax + 1, 0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::vector<double> qi = q.At(nodes[i]);
    double p = 0.0;
    for (int k = 0; k <= n; ++k) p += at_zero[k] * qi[k];
    const std::vector<double> legendre = Legendre(lmax, nodes[i]);
    for (int l = 0; l <= lmax; ++l) w[l] += omega_w[i] * p * p * legendre[l];
  }
  const double w0 = w[0];
  for (double& v : w) v /= w0;
  return w;
}

double KernelMinimumRatio(const std::vector<double>& w) {
  const int lmax = static_cast<int>(w.size()) - 1;
  auto kernel = [&](double x) {
    const std::vector<double> p = Legendre(lmax, x);
    double k = 0.0;
    for (int l = 0; l <= lmax; ++l) k += (2.0 * l + 1.0) * w[l] * p[l];
    return k;
  };
  const double top = kernel(1.0);
  const int points = 64 * (lmax + 1);
  double lowest = top;
  for (int i = 0; i <= points; ++i) lowest = std::min(lowest, kernel(std::cos(kPi * i / points)));
  return lowest / top;
}

}  // namespace prt
