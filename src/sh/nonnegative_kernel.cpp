#include "sh/nonnegative_kernel.h"

#include <algorithm>
#include <cmath>

#include "sh/quadrature.h"

namespace prt {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// P_0(x) .. P_n(x) by the three-term recurrence.
std::vector<double> Legendre(int n, double x) {
  std::vector<double> p(n + 1);
  p[0] = 1.0;
  if (n >= 1) p[1] = x;
  for (int l = 1; l < n; ++l) p[l + 1] = ((2.0 * l + 1.0) * x * p[l] - l * p[l - 1]) / (l + 1.0);
  return p;
}

/// Largest zero of P_N by Newton's method from the asymptotic estimate cos(pi 0.75 / (N + 0.5)).
double LargestLegendreZero(int N) {
  double x = std::cos(kPi * 0.75 / (N + 0.5));
  for (int it = 0; it < 100; ++it) {
    const std::vector<double> p = Legendre(N, x);
    const double derivative = N * (x * p[N] - p[N - 1]) / (x * x - 1.0);
    const double step = p[N] / derivative;
    x -= step;
    if (std::abs(step) < 1e-16) break;
  }
  return x;
}

std::vector<double> SquareKernel(int lmax) {
  const int n = lmax / 2;
  std::vector<double> w(lmax + 1, 0.0);
  if (n == 0) {
    w[0] = 1.0;
    return w;
  }
  const std::vector<double> at_zero = Legendre(n, LargestLegendreZero(n + 1));
  std::vector<double> nodes, weights;
  GaussLegendre(lmax + 2, nodes, weights);  // exact to degree 2 lmax + 3 >= 2n + lmax
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::vector<double> p = Legendre(lmax, nodes[i]);
    double q = 0.0;
    for (int l = 0; l <= n; ++l) q += (2.0 * l + 1.0) * at_zero[l] * p[l];
    for (int l = 0; l <= lmax; ++l) w[l] += weights[i] * q * q * p[l];
  }
  const double w0 = w[0];
  for (double& v : w) v /= w0;
  return w;
}

std::vector<double> PowerCosineKernel(int lmax) {
  std::vector<double> w(lmax + 1, 1.0);
  for (int l = 1; l <= lmax; ++l) w[l] = w[l - 1] * (lmax - l + 1.0) / (lmax + l + 1.0);
  return w;
}

}  // namespace

std::vector<double> NonNegativeKernelWeights(int lmax) {
  if (lmax == 0) return {1.0};
  std::vector<double> square = SquareKernel(lmax), power = PowerCosineKernel(lmax);
  return square[1] >= power[1] ? square : power;
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
