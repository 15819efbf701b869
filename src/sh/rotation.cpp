#include "sh/rotation.h"

#include <cmath>
#include <cstdlib>

namespace prt {
namespace {

/// A band matrix with signed indices m, n in [-l, l].
struct BandView {
  int l;
  const std::vector<double>* d;
  double operator()(int m, int n) const { return (*d)[(m + l) * (2 * l + 1) + (n + l)]; }
};

/// The P function of [1]: one D_1 entry (row i) times one D_{l-1} entry, with the
/// boundary cases |b| = l that reach just outside band l-1.
double P(int i, int a, int b, int l, const BandView& r1, const BandView& prev) {
  if (b == l) return r1(i, 1) * prev(a, l - 1) - r1(i, -1) * prev(a, -l + 1);
  if (b == -l) return r1(i, 1) * prev(a, -l + 1) + r1(i, -1) * prev(a, l - 1);
  return r1(i, 0) * prev(a, b);
}

double U(int m, int n, int l, const BandView& r1, const BandView& prev) {
  return P(0, m, n, l, r1, prev);
}

double V(int m, int n, int l, const BandView& r1, const BandView& prev) {
  if (m == 0) return P(1, 1, n, l, r1, prev) + P(-1, -1, n, l, r1, prev);
  if (m > 0) {
    const double d = (m == 1) ? 1.0 : 0.0;
    return P(1, m - 1, n, l, r1, prev) * std::sqrt(1.0 + d) - P(-1, -m + 1, n, l, r1, prev) * (1.0 - d);
  }
  const double d = (m == -1) ? 1.0 : 0.0;
  return P(1, m + 1, n, l, r1, prev) * (1.0 - d) + P(-1, -m - 1, n, l, r1, prev) * std::sqrt(1.0 + d);
}

double W(int m, int n, int l, const BandView& r1, const BandView& prev) {
  if (m > 0) return P(1, m + 1, n, l, r1, prev) + P(-1, -m - 1, n, l, r1, prev);
  return P(1, m - 1, n, l, r1, prev) - P(-1, -m + 1, n, l, r1, prev);  // m < 0 (w = 0 at m = 0)
}

/// Band l of [1] (no Condon–Shortley phase) from band 1 and band l-1.
std::vector<double> NextBand(int l, const BandView& r1, const BandView& prev) {
  std::vector<double> out((2 * l + 1) * (2 * l + 1));
  for (int m = -l; m <= l; ++m) {
    for (int n = -l; n <= l; ++n) {
      const double d = (m == 0) ? 1.0 : 0.0;
      const double denom = (std::abs(n) == l) ? (2.0 * l) * (2.0 * l - 1.0) : double(l + n) * (l - n);
      const int am = std::abs(m);
      const double u = std::sqrt(double(l + m) * (l - m) / denom);
      const double v = 0.5 * std::sqrt((1.0 + d) * (l + am - 1.0) * (l + am) / denom) * (1.0 - 2.0 * d);
      const double w = -0.5 * std::sqrt((l - am - 1.0) * (l - am) / denom) * (1.0 - d);
      double value = 0.0;
      if (u != 0.0) value += u * U(m, n, l, r1, prev);
      if (v != 0.0) value += v * V(m, n, l, r1, prev);
      if (w != 0.0) value += w * W(m, n, l, r1, prev);
      out[(m + l) * (2 * l + 1) + (n + l)] = value;
    }
  }
  return out;
}

}  // namespace

ShRotation::ShRotation(const glm::dmat3& R, int lmax) : lmax_(lmax), bands_(lmax + 1) {
  bands_[0] = {1.0};
  if (lmax == 0) return;
  // D_1 without the phase: rows/columns in the order (y, z, x). glm is column-major: R[c][r].
  const int axis[3] = {1, 2, 0};
  std::vector<double> r1(9);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r1[i * 3 + j] = R[axis[j]][axis[i]];
  const BandView v1{1, &r1};
  std::vector<std::vector<double>> plain(lmax + 1);
  plain[0] = {1.0};
  plain[1] = r1;
  for (int l = 2; l <= lmax; ++l) plain[l] = NextBand(l, v1, BandView{l - 1, &plain[l - 1]});
  // Condon–Shortley phase: entry (m, n) gets (-1)^(m + n).
  for (int l = 1; l <= lmax; ++l) {
    bands_[l] = plain[l];
    for (int m = -l; m <= l; ++m)
      for (int n = -l; n <= l; ++n)
        if ((std::abs(m) + std::abs(n)) % 2 == 1) bands_[l][(m + l) * (2 * l + 1) + (n + l)] *= -1.0;
  }
}

void ShRotation::Apply(const double* in, double* out) const {
  for (int l = 0; l <= lmax_; ++l) {
    const int size = 2 * l + 1, base = l * l;
    const double* d = bands_[l].data();
    for (int i = 0; i < size; ++i) {
      double sum = 0.0;
      for (int j = 0; j < size; ++j) sum += d[i * size + j] * in[base + j];
      out[base + i] = sum;
    }
  }
}

ShRgb ShRotation::Apply(const ShRgb& in) const {
  const int lmax = LmaxOfCount(in.size());
  ShRgb out(in.size(), glm::dvec3(0.0));
  for (int l = 0; l <= lmax && l <= lmax_; ++l) {
    const int size = 2 * l + 1, base = l * l;
    const double* d = bands_[l].data();
    for (int i = 0; i < size; ++i) {
      glm::dvec3 sum(0.0);
      for (int j = 0; j < size; ++j) sum += d[i * size + j] * in[base + j];
      out[base + i] = sum;
    }
  }
  return out;
}

ShRgb RotateAboutZ(const ShRgb& in, double a) {
  const int lmax = LmaxOfCount(in.size());
  ShRgb out = in;
  for (int m = 1; m <= lmax; ++m) {
    const double c = std::cos(m * a), s = std::sin(m * a);
    for (int l = m; l <= lmax; ++l) {
      const glm::dvec3 cm = in[ShIndex(l, m)], sm = in[ShIndex(l, -m)];
      out[ShIndex(l, m)] = c * cm - s * sm;
      out[ShIndex(l, -m)] = s * cm + c * sm;
    }
  }
  return out;
}

glm::dmat3 AxisAngle(const glm::dvec3& axis, double a) {
  const glm::dvec3 k = axis / std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
  const double c = std::cos(a), s = std::sin(a), t = 1.0 - c;
  // Rodrigues: R = c I + s [k]x + t k k^T; glm is column-major (R[col][row]).
  glm::dmat3 R;
  R[0] = {c + t * k.x * k.x, t * k.x * k.y + s * k.z, t * k.x * k.z - s * k.y};
  R[1] = {t * k.x * k.y - s * k.z, c + t * k.y * k.y, t * k.y * k.z + s * k.x};
  R[2] = {t * k.x * k.z + s * k.y, t * k.y * k.z - s * k.x, c + t * k.z * k.z};
  return R;
}

}  // namespace prt
