#include "sh/basis.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/simd.h"

namespace prt {
namespace {

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
  double c = 1.0, s = 0.0;         // Re, Im of (x + i y)^m
  for (int m = 0; m <= lmax; ++m) {
    // Q_m and sqrt(2m + 3) from the table: the same products as computing them here, no sqrt.
    const double q = t.q[m];
    if (m > 0) {
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
        p = t.c1[m] * z * q;
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

namespace {

// Kernels per instruction set on core/simd.h's vectors, each where it is one register: V2 in
// the baseline, V4 under AVX2, V8 under AVX-512. Everything on vectors is forced inline, so
// -Wpsabi's warning (vectors passed by value depend on the instruction set) does not apply.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
using simd::Load;
using simd::Store;
using simd::V2;
using simd::V4;
using simd::V8;

/// Calls sink(k, y) for every k < CoeffCount(lmax), y[g] holding Y_k of the directions
/// (x[g], y[g], z[g]) lane by lane, g < G: the recurrence of basis.h in registers, m outer and
/// l inner, G independent vectors interleaved. Every lane rounds the same way: (x + i y)^m by
/// complex products, Y_lm = Pbar_lm for m = 0, else (Pbar_lm sqrt 2) times Re or Im.
template <class V, int G, class Sink>
PRT_SIMD_INLINE void BasisLanes(int lmax, const V* x, const V* y, const V* z, Sink&& sink) {
  const RecurrenceTable& t = Table();
  constexpr double kSqrt2 = 1.4142135623730951;
  V c[G], s[G], p1[G], p2[G], re[G], im[G];  // (x + i y)^m; Pbar_{l-1,m}, Pbar_{l-2,m}; Y_{l,+-m}
  for (int g = 0; g < G; ++g) c[g] = V{} + 1.0, s[g] = V{};
  for (int m = 0; m <= lmax; ++m) {
    if (m > 0)
      for (int g = 0; g < G; ++g) {
        const V cn = c[g] * x[g] - s[g] * y[g];
        s[g] = c[g] * y[g] + s[g] * x[g];
        c[g] = cn;
      }
    const double qm = t.q[m];  // l = m
    for (int g = 0; g < G; ++g) p1[g] = V{} + qm, p2[g] = V{};
    if (m == 0) {
      sink(0, p1);
    } else {
      for (int g = 0; g < G; ++g) re[g] = (qm * kSqrt2) * c[g], im[g] = (qm * kSqrt2) * s[g];
      sink(ShIndex(m, m), re);
      sink(ShIndex(m, -m), im);
    }
    for (int l = m + 1; l <= lmax; ++l) {
      const double a = (l == m + 1) ? t.c1[m] : t.a[ShIndex(l, m)];
      const double b = (l == m + 1) ? 0.0 : t.b[ShIndex(l, m)];
      for (int g = 0; g < G; ++g) {
        const V p = a * (z[g] * p1[g] - b * p2[g]);
        p2[g] = p1[g];
        p1[g] = p;
      }
      if (m == 0) {
        sink(ShIndex(l, 0), p1);
        continue;
      }
      for (int g = 0; g < G; ++g) {
        const V ps = p1[g] * kSqrt2;
        re[g] = ps * c[g], im[g] = ps * s[g];
      }
      sink(ShIndex(l, m), re);
      sink(ShIndex(l, -m), im);
    }
  }
}

/// G vectors V of consecutive directions from `first`: x, y, z and the three weights.
template <class V, int G>
struct Group {
  static constexpr std::size_t kCount = G * sizeof(V) / sizeof(double);
  static_assert(kCount % 4 == 0, "a group covers each of the four partial sums equally");
  V x[G], y[G], z[G], w[3][G];

  PRT_SIMD_INLINE Group(std::size_t first, const double* const in[6]) {
    for (int g = 0; g < G; ++g) {
      const std::size_t i = first + g * sizeof(V) / sizeof(double);
      x[g] = Load<V>(in[0] + i), y[g] = Load<V>(in[1] + i), z[g] = Load<V>(in[2] + i);
      for (int c = 0; c < 3; ++c) w[c][g] = Load<V>(in[3 + c] + i);
    }
  }
};

/// Adds the terms y[g] w[g], g < G, of consecutive directions to the four partial sums at acc
/// (lane j sums the directions i = j mod 4), each lane's terms in direction order. A group
/// starts at a multiple of four directions.
template <class V, int G>
PRT_SIMD_INLINE void AddTerms(double* acc, const V* y, const V* w) {
  if constexpr (sizeof(V) == sizeof(V2)) {  // vector g covers lanes 2 (g mod 2), +1
    V2 a[2] = {Load<V2>(acc), Load<V2>(acc + 2)};
    for (int g = 0; g < G; ++g) a[g % 2] = a[g % 2] + y[g] * w[g];
    Store(acc, a[0]), Store(acc + 2, a[1]);
  } else if constexpr (sizeof(V) == sizeof(V4)) {
    V4 a = Load<V4>(acc);
    for (int g = 0; g < G; ++g) a = a + y[g] * w[g];
    Store(acc, a);
  } else {  // a V8's first four directions, then its last four
    V4 a = Load<V4>(acc);
    for (int g = 0; g < G; ++g) {
      const V8 t = y[g] * w[g];
      a = (a + __builtin_shufflevector(t, t, 0, 1, 2, 3)) + __builtin_shufflevector(t, t, 4, 5, 6, 7);
    }
    Store(acc, a);
  }
}

/// ProjectBasisBatch into acc (the partial sums of channel c, coefficient k at acc + 4 (c count +
/// k)), with groups of G vectors V, then four directions at a time, then the last n mod 4 one by
/// one onto lane 0. G interleaved vectors hide the recurrence's latency (measured at lmax 8, one
/// thread, AMD EPYC of lscpu family 26: G = 4 took 3-5 % less time than G = 2 and 10-20 % less
/// than G = 1 with each of V2, V4 and V8).
template <class V, int G>
PRT_SIMD_INLINE void ProjectBatchBody(int lmax, std::size_t n, const double* const in[6], double* acc) {
  const std::size_t count = CoeffCount(lmax);
  double* ar = acc;
  double* ag = ar + 4 * count;
  double* ab = ag + 4 * count;
  std::size_t i = 0;
  for (; i + Group<V, G>::kCount <= n; i += Group<V, G>::kCount) {
    const Group<V, G> d(i, in);
    BasisLanes<V, G>(lmax, d.x, d.y, d.z, [&](int k, const V* y) {
      AddTerms<V, G>(ar + 4 * k, y, d.w[0]);
      AddTerms<V, G>(ag + 4 * k, y, d.w[1]);
      AddTerms<V, G>(ab + 4 * k, y, d.w[2]);
    });
  }
  for (; i + 4 <= n; i += 4) {
    const Group<V2, 2> d(i, in);
    BasisLanes<V2, 2>(lmax, d.x, d.y, d.z, [&](int k, const V2* y) {
      AddTerms<V2, 2>(ar + 4 * k, y, d.w[0]);
      AddTerms<V2, 2>(ag + 4 * k, y, d.w[1]);
      AddTerms<V2, 2>(ab + 4 * k, y, d.w[2]);
    });
  }
  if (i == n) return;
  double tail[6][4];  // the last directions, padded with copies of the last one
  for (int c = 0; c < 6; ++c)
    for (std::size_t j = 0; j < 4; ++j) tail[c][j] = in[c][std::min(i + j, n - 1)];
  const double* const padded[6] = {tail[0], tail[1], tail[2], tail[3], tail[4], tail[5]};
  const Group<V2, 2> d(0, padded);
  BasisLanes<V2, 2>(lmax, d.x, d.y, d.z, [&](int k, const V2* y) {
    for (std::size_t j = 0; i + j < n; ++j) {
      const double yj = y[j / 2][j % 2];
      ar[4 * k] += yj * tail[3][j];
      ag[4 * k] += yj * tail[4][j];
      ab[4 * k] += yj * tail[5][j];
    }
  });
}

// One kernel per instruction set, chosen once for the CPU at hand.
using BatchKernel = void (*)(int lmax, std::size_t n, const double* const in[6], double* acc);

void ProjectBatch2(int lmax, std::size_t n, const double* const in[6], double* acc) {
  ProjectBatchBody<V2, 4>(lmax, n, in, acc);
}
#ifdef PRT_TARGET_X86_64_V4  // and PRT_TARGET_AVX2, defined with it
PRT_TARGET_AVX2 void ProjectBatch4(int lmax, std::size_t n, const double* const in[6], double* acc) {
  ProjectBatchBody<V4, 4>(lmax, n, in, acc);
}
PRT_TARGET_X86_64_V4 void ProjectBatch8(int lmax, std::size_t n, const double* const in[6], double* acc) {
  ProjectBatchBody<V8, 4>(lmax, n, in, acc);
}
#endif

/// EvalBasisBatch with groups of G vectors V, then pairs, then the last direction (its pair
/// padded with a copy): every lane rounds as BasisLanes does, so every kernel writes the same.
template <class V, int G>
PRT_SIMD_INLINE void EvalBatchBody(int lmax, std::size_t n, const double* const in[3], double* out) {
  const std::size_t count = CoeffCount(lmax);
  constexpr std::size_t kLanes = sizeof(V) / sizeof(double);
  std::size_t i = 0;
  for (; i + G * kLanes <= n; i += G * kLanes) {
    V x[G], y[G], z[G];
    for (int g = 0; g < G; ++g) {
      x[g] = Load<V>(in[0] + i + g * kLanes), y[g] = Load<V>(in[1] + i + g * kLanes), z[g] = Load<V>(in[2] + i + g * kLanes);
    }
    BasisLanes<V, G>(lmax, x, y, z, [&](int k, const V* v) {
      for (int g = 0; g < G; ++g)
        for (std::size_t j = 0; j < kLanes; ++j) out[(i + g * kLanes + j) * count + std::size_t(k)] = v[g][j];
    });
  }
  for (; i < n; i += 2) {
    const std::size_t last = std::min(i + 1, n - 1);
    const V2 x[1] = {V2{in[0][i], in[0][last]}}, y[1] = {V2{in[1][i], in[1][last]}}, z[1] = {V2{in[2][i], in[2][last]}};
    BasisLanes<V2, 1>(lmax, x, y, z, [&](int k, const V2* v) {
      out[i * count + std::size_t(k)] = v[0][0];
      if (i + 1 < n) out[(i + 1) * count + std::size_t(k)] = v[0][1];
    });
  }
}

using EvalKernel = void (*)(int lmax, std::size_t n, const double* const in[3], double* out);

void EvalBatch2(int lmax, std::size_t n, const double* const in[3], double* out) { EvalBatchBody<V2, 4>(lmax, n, in, out); }
#ifdef PRT_TARGET_X86_64_V4
PRT_TARGET_AVX2 void EvalBatch4(int lmax, std::size_t n, const double* const in[3], double* out) {
  EvalBatchBody<V4, 4>(lmax, n, in, out);
}
PRT_TARGET_X86_64_V4 void EvalBatch8(int lmax, std::size_t n, const double* const in[3], double* out) {
  EvalBatchBody<V8, 2>(lmax, n, in, out);
}
#endif

EvalKernel EvalKernelFor(VectorLevel level) {
#ifdef PRT_TARGET_X86_64_V4
  switch (level) {
    case VectorLevel::kX86_64V4: return EvalBatch8;
    case VectorLevel::kAvx2: return EvalBatch4;
    case VectorLevel::kBaseline: break;
  }
#endif
  return EvalBatch2;
}

BatchKernel KernelFor(VectorLevel level) {
#ifdef PRT_TARGET_X86_64_V4
  switch (level) {
    case VectorLevel::kX86_64V4: return ProjectBatch8;
    case VectorLevel::kAvx2: return ProjectBatch4;
    case VectorLevel::kBaseline: break;
  }
#endif
  return ProjectBatch2;
}

}  // namespace

void ProjectBasisBatch(int lmax, std::size_t n, const double* x, const double* y, const double* z,
                       const double* wr, const double* wg, const double* wb, double* sums) {
  static const VectorLevel level = CpuVectorLevel();
  ProjectBasisBatchAt(level, lmax, n, x, y, z, wr, wg, wb, sums);
}

void ProjectBasisBatchAt(VectorLevel level, int lmax, std::size_t n, const double* x, const double* y,
                         const double* z, const double* wr, const double* wg, const double* wb, double* sums) {
  const BatchKernel kernel = KernelFor(std::min(level, CpuVectorLevel()));
  const std::size_t count = CoeffCount(lmax);
  // Four partial sums per channel and coefficient: plain doubles, because a vector type's
  // alignment depends on the instruction set.
  std::vector<double> acc(12 * count, 0.0);
  const double* const in[6] = {x, y, z, wr, wg, wb};
  kernel(lmax, n, in, acc.data());
  for (std::size_t k = 0; k < 3 * count; ++k) {
    const double* a = acc.data() + 4 * k;
    sums[k] += (a[0] + a[1]) + (a[2] + a[3]);
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

void EvalBasisBatch(int lmax, std::size_t n, const double* x, const double* y, const double* z, double* out) {
  static const VectorLevel level = CpuVectorLevel();
  EvalBasisBatchAt(level, lmax, n, x, y, z, out);
}

void EvalBasisBatchAt(VectorLevel level, int lmax, std::size_t n, const double* x, const double* y, const double* z,
                      double* out) {
  const double* const in[3] = {x, y, z};
  EvalKernelFor(std::min(level, CpuVectorLevel()))(lmax, n, in, out);
}

}  // namespace prt
