#include "sh/basis.h"

#include <cmath>

#include "core/simd.h"

namespace prt {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// a_lm and b_lm of the recurrence for every (l, m) with l <= kMaxBasisLmax, built once.
struct RecurrenceTable {
  std::vector<double> a, b;  // indexed by ShIndex(l, m), m >= 0
  std::vector<double> q;     // Q_m, the l = m start values (sign included)
  std::vector<double> c1;    // sqrt(2m + 3), the l = m + 1 factor
  RecurrenceTable()
      : a(CoeffCount(kMaxBasisLmax)), b(CoeffCount(kMaxBasisLmax)), q(kMaxBasisLmax + 1),
        c1(kMaxBasisLmax + 1) {
    q[0] = 0.28209479177387814;  // 1/sqrt(4 pi)
    for (int m = 1; m <= kMaxBasisLmax; ++m) q[m] = -std::sqrt((2.0 * m + 1.0) / (2.0 * m)) * q[m - 1];
    for (int m = 0; m <= kMaxBasisLmax; ++m) c1[m] = std::sqrt(2.0 * m + 3.0);
    for (int l = 2; l <= kMaxBasisLmax; ++l) {
      for (int m = 0; m <= l - 2; ++m) {
        const double l2 = double(l) * l, m2 = double(m) * m, lm1 = double(l - 1);
        a[ShIndex(l, m)] = std::sqrt((4.0 * l2 - 1.0) / (l2 - m2));
        b[ShIndex(l, m)] = std::sqrt((lm1 * lm1 - m2) / (4.0 * lm1 * lm1 - 1.0));
      }
    }
  }
};

const RecurrenceTable& Table() {
  static const RecurrenceTable table;
  return table;
}

}  // namespace

ShRgb FirstBands(const ShRgb& light, int lmax) {
  return ShRgb(light.begin(), light.begin() + std::min(light.size(), std::size_t(CoeffCount(lmax))));
}

int LmaxOfCount(std::size_t count) {
  const auto r = static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(count))));
  return (r > 0 && r * r == count) ? static_cast<int>(r) - 1 : -1;
}

void EvalBasisBand2(const glm::dvec3& d, double* out) {
  const double x = d.x, y = d.y, z = d.z;
  out[0] = 0.28209479177387814;           // 1/(2 sqrt(pi))
  out[1] = -0.48860251190291992 * y;      // sqrt(3/(4 pi))
  out[2] = 0.48860251190291992 * z;
  out[3] = -0.48860251190291992 * x;
  out[4] = 1.0925484305920792 * x * y;    // sqrt(15/(4 pi))
  out[5] = -1.0925484305920792 * y * z;
  out[6] = 0.31539156525252005 * (3.0 * z * z - 1.0);  // sqrt(5/(16 pi))
  out[7] = -1.0925484305920792 * x * z;
  out[8] = 0.54627421529603959 * (x * x - y * y);      // sqrt(15/(16 pi))
}

void EvalBasisRecurrence(int lmax, const glm::dvec3& d, double* out) {
  const RecurrenceTable& t = Table();
  const double z = d.z;
  double q = 0.28209479177387814;  // Q_0 = 1/sqrt(4 pi)
  double c = 1.0, s = 0.0;         // Re, Im of (x + i y)^m
  for (int m = 0; m <= lmax; ++m) {
    if (m > 0) {
      q *= -std::sqrt((2.0 * m + 1.0) / (2.0 * m));
      const double c1 = c * d.x - s * d.y;
      s = c * d.y + s * d.x;
      c = c1;
    }
    // Scale of the cosine/sine parts: sqrt(2) for m > 0.
    const double cs = (m == 0) ? 1.0 : 1.4142135623730951 * c;
    const double sn = 1.4142135623730951 * s;
    double p2 = 0.0, p1 = q;  // Pbar_{l-2,m}, Pbar_{l-1,m}; start at l = m
    for (int l = m; l <= lmax; ++l) {
      double p;
      if (l == m) {
        p = q;
      } else if (l == m + 1) {
        p = std::sqrt(2.0 * m + 3.0) * z * q;
      } else {
        const int k = ShIndex(l, m);
        p = t.a[k] * (z * p1 - t.b[k] * p2);
      }
      if (l > m) {
        p2 = p1;
        p1 = p;
      }
      out[ShIndex(l, m)] = p * cs;
      if (m > 0) out[ShIndex(l, -m)] = p * sn;
    }
  }
}

void EvalBasis(int lmax, const glm::dvec3& dir, double* out) {
  if (lmax <= 2) {
    double tmp[9];
    EvalBasisBand2(dir, tmp);
    for (int k = 0; k < CoeffCount(lmax); ++k) out[k] = tmp[k];
    return;
  }
  EvalBasisRecurrence(lmax, dir, out);
}

PRT_VECTORIZED
void EvalBasisBatch(int lmax, std::size_t n, const double* x, const double* y, const double* z,
                    double* out, std::size_t stride) {
  const RecurrenceTable& t = Table();
  constexpr double kSqrt2 = 1.4142135623730951;
  // Per direction: Re/Im of (x + i y)^m, and the last two Pbar values of the current m.
  std::vector<double> buffer(4 * n);
  double* c = buffer.data();
  double* s = c + n;
  double* p1 = s + n;
  double* p2 = p1 + n;
  for (std::size_t i = 0; i < n; ++i) c[i] = 1.0, s[i] = 0.0;
  for (int m = 0; m <= lmax; ++m) {
    if (m > 0) {
      for (std::size_t i = 0; i < n; ++i) {
        const double cn = c[i] * x[i] - s[i] * y[i];
        s[i] = c[i] * y[i] + s[i] * x[i];
        c[i] = cn;
      }
    }
    const double qm = t.q[m];
    double* pos = out + ShIndex(m, m) * stride;
    double* neg = out + ShIndex(m, -m) * stride;
    const double scale = (m == 0) ? 1.0 : kSqrt2;
    for (std::size_t i = 0; i < n; ++i) {  // l = m
      p2[i] = 0.0;
      p1[i] = qm;
      pos[i] = qm * scale * c[i];
      if (m > 0) neg[i] = qm * kSqrt2 * s[i];
    }
    for (int l = m + 1; l <= lmax; ++l) {
      pos = out + ShIndex(l, m) * stride;
      neg = out + ShIndex(l, -m) * stride;
      const double a = (l == m + 1) ? t.c1[m] : t.a[ShIndex(l, m)];
      const double b = (l == m + 1) ? 0.0 : t.b[ShIndex(l, m)];
      for (std::size_t i = 0; i < n; ++i) {
        const double p = a * (z[i] * p1[i] - b * p2[i]);
        p2[i] = p1[i];
        p1[i] = p;
        pos[i] = p * scale * c[i];
      }
      if (m > 0)
        for (std::size_t i = 0; i < n; ++i) neg[i] = p1[i] * kSqrt2 * s[i];
    }
  }
}

std::vector<double> EvalBasis(int lmax, const glm::dvec3& dir) {
  std::vector<double> out(CoeffCount(lmax));
  EvalBasis(lmax, dir, out.data());
  return out;
}

long double EvalBasisReference(int l, int m, const glm::dvec3& dir) {
  const int am = std::abs(m);
  const long double z = dir.z;
  const long double sint = std::sqrt((1.0L - z) * (1.0L + z));
  // Unnormalised P_m^m = (-1)^m (2m-1)!! sin^m, then the usual three-term recurrence in l.
  long double pmm = 1.0L;
  for (int i = 1; i <= am; ++i) pmm *= -(2.0L * i - 1.0L) * sint;
  long double p = pmm;
  if (l > am) {
    long double pm1 = pmm, pm2 = 0.0L;
    for (int ll = am + 1; ll <= l; ++ll) {
      p = ((2.0L * ll - 1.0L) * z * pm1 - (ll + am - 1.0L) * pm2) / (ll - am);
      pm2 = pm1;
      pm1 = p;
    }
  }
  long double ratio = 1.0L;  // (l-|m|)! / (l+|m|)!
  for (int i = l - am + 1; i <= l + am; ++i) ratio /= i;
  const long double k = std::sqrt((2.0L * l + 1.0L) / (4.0L * 3.141592653589793238462643383279502884L) * ratio);
  const long double phi = std::atan2(static_cast<long double>(dir.y), static_cast<long double>(dir.x));
  if (m == 0) return k * p;
  const long double sqrt2 = 1.414213562373095048801688724209698079L;
  return m > 0 ? sqrt2 * k * p * std::cos(am * phi) : sqrt2 * k * p * std::sin(am * phi);
}

}  // namespace prt
