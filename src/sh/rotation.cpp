#include "sh/rotation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <glm/matrix.hpp>

#include "core/error.h"
#include "core/text.h"
#include "sh/wigner_d.h"

namespace prt {
namespace {

constexpr double kSqrt2 = 1.41421356237309504880;

struct Zyz {
  double alpha, beta, gamma;
};

/// R = Rz(alpha) Ry(beta) Rz(gamma). beta from atan2 (acos loses digits near 0 and pi); gamma
/// from what Rz(alpha) Ry(beta) leaves of R, so the product reproduces R to rounding even where
/// alpha alone is ill-determined (beta near 0 or pi).
Zyz ZyzAngles(const glm::dmat3& R) {
  auto M = [&](int row, int col) { return R[col][row]; };
  Zyz e{};
  e.beta = std::atan2(std::hypot(M(0, 2), M(1, 2)), M(2, 2));
  e.alpha = std::atan2(M(1, 2), M(0, 2));
  const glm::dmat3 rest = glm::transpose(AxisAngle({0, 0, 1}, e.alpha) * AxisAngle({0, 1, 0}, e.beta)) * R;
  e.gamma = std::atan2(rest[0][1], rest[0][0]);
  return e;
}

/// cos(m a) and sin(m a) for m = 0..lmax.
struct Turn {
  std::vector<double> c, s;
  Turn(double a, int lmax) : c(lmax + 1), s(lmax + 1) {
    for (int m = 0; m <= lmax; ++m) c[m] = std::cos(m * a), s[m] = std::sin(m * a);
  }
};

/// D := Z(a) D for band l, Z(a) = D_l(Rz(a)): rows m and -m mix by cos(m a), sin(m a).
void TurnRows(std::vector<double>& D, int l, const Turn& a) {
  const int n = 2 * l + 1;
  for (int m = 1; m <= l; ++m) {
    const double c = a.c[m], s = a.s[m];
    double* top = &D[(l + m) * n];
    double* bottom = &D[(l - m) * n];
    for (int j = 0; j < n; ++j) {
      const double t = top[j], b = bottom[j];
      top[j] = c * t - s * b;
      bottom[j] = s * t + c * b;
    }
  }
}

/// D := D Z(a) for band l.
void TurnColumns(std::vector<double>& D, int l, const Turn& a) {
  const int n = 2 * l + 1;
  for (int m = 1; m <= l; ++m) {
    const double c = a.c[m], s = a.s[m];
    for (int i = 0; i < n; ++i) {
      double& pos = D[i * n + l + m];
      double& neg = D[i * n + l - m];
      const double p = pos, q = neg;
      pos = c * p + s * q;
      neg = c * q - s * p;
    }
  }
}

/// Real band matrices of Ry(beta) from Wigner's d. With A_{mk} = d^l_{mk}(beta) (the complex
/// harmonics obey Y^m(Ry d) = sum_k A_{mk} Y^k(d)) and our real harmonics y_{l,+-m} = sqrt(2)
/// Re/Im Y^m (m > 0), y_{l0} = Y^0, taking real and imaginary parts (Y^{-k} = (-1)^k conj Y^k):
///   D[m][k]  = A_{mk} + (-1)^k A_{m,-k},   D[-m][-k] = A_{mk} - (-1)^k A_{m,-k}   (m, k > 0)
///   D[m][0]  = sqrt(2) A_{m0},   D[0][k] = (A_{0k} + (-1)^k A_{0,-k}) / sqrt(2),   D[0][0] = A_00,
/// and zero between the cosine (m >= 0) and sine (m < 0) halves, which Ry never mixes.
std::vector<std::vector<double>> AboutY(double beta, int lmax) {
  std::vector<std::vector<double>> bands(lmax + 1);
  for (int l = 0; l <= lmax; ++l) bands[l].assign((2 * l + 1) * (2 * l + 1), 0.0);
  std::vector<double> plus(lmax + 1), minus(lmax + 1);
  for (int m = 0; m <= lmax; ++m) {
    for (int k = 0; k <= lmax; ++k) {
      WignerDRun(m, k, beta, lmax, plus.data());
      if (k > 0) WignerDRun(m, -k, beta, lmax, minus.data());  // k = 0 reads plus only
      const double sign = (k % 2 == 0) ? 1.0 : -1.0;
      for (int l = std::max(m, k); l <= lmax; ++l) {
        const int n = 2 * l + 1;
        double* D = bands[l].data();
        if (k == 0) {
          D[(l + m) * n + l] = (m == 0) ? plus[l] : kSqrt2 * plus[l];
        } else if (m == 0) {
          D[l * n + l + k] = (plus[l] + sign * minus[l]) / kSqrt2;
        } else {
          D[(l + m) * n + l + k] = plus[l] + sign * minus[l];
          D[(l - m) * n + l - k] = plus[l] - sign * minus[l];
        }
      }
    }
  }
  return bands;
}

}  // namespace

ShRotation::ShRotation(const glm::dmat3& R, int lmax) : lmax_(lmax) {
  if (lmax < 0 || lmax > kMaxBasisLmax)
    throw Error(Formatted("SH rotation: lmax %d is outside 0..%d, the bands it is exact for", lmax, kMaxBasisLmax));
  const Zyz e = ZyzAngles(R);
  bands_ = AboutY(e.beta, lmax);
  const Turn alpha(e.alpha, lmax), gamma(e.gamma, lmax);
  for (int l = 1; l <= lmax; ++l) {
    TurnColumns(bands_[l], l, gamma);
    TurnRows(bands_[l], l, alpha);
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

ShRgb ShRotation::Apply(const ShRgb& in, bool transposed) const {
  const int lmax = LmaxOfCount(in.size());
  ShRgb out(in.size(), glm::dvec3(0.0));
  for (int l = 0; l <= lmax && l <= lmax_; ++l) {
    const int size = 2 * l + 1, base = l * l;
    const double* d = bands_[l].data();
    // Entry (i, j) of D, or of D^T = D(R^T), the inverse rotation.
    const int row_stride = transposed ? 1 : size, column_stride = transposed ? size : 1;
    for (int i = 0; i < size; ++i) {
      glm::dvec3 sum(0.0);
      for (int j = 0; j < size; ++j) sum += d[i * row_stride + j * column_stride] * in[base + j];
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
