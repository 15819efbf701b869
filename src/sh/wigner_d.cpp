#include "sh/wigner_d.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "sh/coeffs.h"

namespace prt {
namespace {

/// lgamma(n + 1) for n = 0..2 kMaxBasisLmax + 1, computed once (the same numbers as calling it).
long double LogFactorial(int n) {
  static const std::vector<long double> table = [] {
    std::vector<long double> t(2 * kMaxBasisLmax + 2);
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = std::lgamma(static_cast<long double>(i) + 1.0L);
    return t;
  }();
  return n < int(table.size()) ? table[n] : std::lgamma(static_cast<long double>(n) + 1.0L);
}

/// cos, sin of beta/2 and their logarithms, kept per thread for the last beta: a rotation's
/// (2 lmax + 1)^2 runs share one beta.
struct HalfAngle {
  double beta = std::numeric_limits<double>::quiet_NaN();
  long double c = 0, s = 0, log_c = 0, log_s = 0;
};

const HalfAngle& HalfAngleOf(double beta) {
  thread_local HalfAngle h;
  if (!(h.beta == beta)) {
    h.beta = beta;
    h.c = std::cos(0.5L * beta), h.s = std::sin(0.5L * beta);
    h.log_c = h.c > 0 ? std::log(h.c) : 0.0L;
    h.log_s = h.s > 0 ? std::log(h.s) : 0.0L;
  }
  return h;
}

/// d^j_{j,k}(beta) with j = l0 >= |k| (the first closed form of the header).
long double TopRow(int j, int k, const HalfAngle& h) {
  const long double log_binomial = 0.5L * (LogFactorial(2 * j) - LogFactorial(j + k) - LogFactorial(j - k));
  const int pc = j + k, ps = j - k;
  if ((pc > 0 && h.c == 0) || (ps > 0 && h.s == 0)) return 0.0L;
  long double log_value = log_binomial;
  if (pc > 0) log_value += pc * h.log_c;
  if (ps > 0) log_value += ps * h.log_s;
  const long double sign = ((j - k) % 2 == 0) ? 1.0L : -1.0L;
  return sign * std::exp(log_value);
}

/// d^{l0}_{mk} with l0 = max(|m|, |k|), by the symmetries of the header.
double Start(int m, int k, double beta) {
  const HalfAngle& h = HalfAngleOf(beta);
  const int l0 = std::max(std::abs(m), std::abs(k));
  auto parity = [](int n) { return (n % 2 == 0) ? 1.0L : -1.0L; };
  if (m == l0) return double(TopRow(l0, k, h));
  if (k == -l0) return double(TopRow(l0, -m, h));                    // d_{mk} = d_{-k,-m}
  if (k == l0) return double(parity(m - k) * TopRow(l0, m, h));      // d_{mk} = (-1)^(m-k) d_{km}
  return double(parity(l0 + k) * TopRow(l0, -k, h));                 // m = -l0: = d_{-k,l0}
}

}  // namespace

void WignerDRun(int m, int k, double beta, int lmax, double* out) {
  const int l0 = std::max(std::abs(m), std::abs(k));
  if (l0 > lmax) return;
  const double cb = std::cos(beta);
  const double mk = double(m) * k, m2 = double(m) * m, k2 = double(k) * k;
  double prev = 0.0, cur = Start(m, k, beta);
  out[l0] = cur;
  for (int l = l0; l < lmax; ++l) {
    const double lf = l, l1 = l + 1.0;
    double next;
    if (l == 0) {
      next = cb * cur;  // m = k = 0: Legendre P_1
    } else {
      const double lhs = lf * std::sqrt((l1 * l1 - m2) * (l1 * l1 - k2));
      next = ((2.0 * lf + 1.0) * (lf * l1 * cb - mk) * cur - l1 * std::sqrt((lf * lf - m2) * (lf * lf - k2)) * prev) / lhs;
    }
    prev = cur;
    cur = next;
    out[l + 1] = cur;
  }
}

double WignerDExplicit(int l, int m, int k, double beta) {
  const long double c = std::cos(0.5L * beta), s = std::sin(0.5L * beta);
  auto fact = [](int n) { return std::tgamma(n + 1.0L); };
  long double sum = 0.0L;
  for (int t = std::max(0, k - m); t <= std::min(l + k, l - m); ++t) {
    const long double term = std::pow(c, 2 * l + k - m - 2 * t) * std::pow(s, m - k + 2 * t) /
                             (fact(l + k - t) * fact(t) * fact(m - k + t) * fact(l - m - t));
    sum += ((m - k + t) % 2 == 0) ? term : -term;
  }
  return double(std::sqrt(fact(l + m) * fact(l - m) * fact(l + k) * fact(l - k)) * sum);
}

}  // namespace prt
