#pragma once
/// \file
/// Real spherical harmonics Y_lm on the unit sphere: orthonormal, Condon–Shortley phase included,
/// polar axis +Z (the convention of Sloan's `SHEval` and google/spherical-harmonics):
///
///   Y_l0        = K_l0 P_l^0(z)
///   Y_lm (m>0)  = sqrt(2) K_lm P_l^m(z) cos(m phi)
///   Y_l-m (m>0) = sqrt(2) K_lm P_l^m(z) sin(m phi)        K_lm = sqrt((2l+1)/(4 pi) (l-m)!/(l+m)!)
///
/// Evaluation uses no trigonometry and no factorials. With s = sin(theta),
/// P_l^m(z) = s^m Pbar_l^m(z) where Pbar is a polynomial in z, and s^m cos(m phi), s^m sin(m phi)
/// are the real and imaginary parts of (x + i y)^m. The normalised Pbar obey [1, 2]
///
///   Q_0 = 1/sqrt(4 pi),  Q_m = -sqrt((2m+1)/(2m)) Q_{m-1}            (l = m)
///   Pbar_{m+1,m} = sqrt(2m+3) z Q_m                                   (l = m+1)
///   Pbar_{l,m}   = a_lm (z Pbar_{l-1,m} - b_lm Pbar_{l-2,m})          (l >= m+2)
///   a_lm = sqrt((4l^2-1)/(l^2-m^2)),  b_lm = sqrt(((l-1)^2-m^2)/(4(l-1)^2-1))
///
/// which stay finite for every l <= 200 at every direction, poles included (the factorial form
/// underflows to 0 at l = m = 86 in double). Accurate to 1e-12 of a long-double reference up to
/// lmax 64 (tests/sh/test_basis.cpp).
///
/// References
/// [1] Holmes, Featherstone, "A unified approach to the Clenshaw summation and the recursive
///     computation of very high degree and order normalised associated Legendre functions",
///     J. Geodesy 76, 2002.
/// [2] Sloan, "Efficient Spherical Harmonic Evaluation", JCGT 2(2), 2013.

#include <vector>

#include <glm/vec3.hpp>

#include "core/simd.h"
#include "sh/coeffs.h"

namespace prt {

/// Writes Y_k(dir) for k < CoeffCount(lmax) to out. dir must be unit length; 0 <= lmax <= 200.
/// Uses the closed forms below for lmax <= 2 and the recurrence above otherwise.
void EvalBasis(int lmax, const glm::dvec3& dir, double* out);
std::vector<double> EvalBasis(int lmax, const glm::dvec3& dir);

/// The recurrence for any lmax (what EvalBasis uses above band 2).
void EvalBasisRecurrence(int lmax, const glm::dvec3& dir, double* out);

/// Weighted basis sums over a batch, what light projection uses: adds
/// sum_i Y_k(dir_i) w_c[i] to sums[c * count + k] for the channels c = r, g, b, k < count =
/// CoeffCount(lmax). Every direction rounds the same way: (x + i y)^m by complex products,
/// Y_lm = Pbar_lm for m = 0 and (Pbar_lm sqrt 2) times Re or Im otherwise (EvalBasisRecurrence
/// rounds differently). The basis values never leave registers (no count x n table is written). Kernels for SSE2, AVX2 and AVX-512 (core/simd.h), picked for
/// the CPU at hand, take each sum in one order: four partial sums s_j of the terms i = j mod 4
/// in increasing i (the last n mod 4 terms go to s_0), then (s_0 + s_1) + (s_2 + s_3) is added
/// to sums. So the result is the same, bit for bit, on every CPU.
void ProjectBasisBatch(int lmax, std::size_t n, const double* x, const double* y, const double* z,
                       const double* wr, const double* wg, const double* wb, double* sums);

/// ProjectBasisBatch with the kernel of `level`, or of the widest level below it that this CPU
/// runs (tests compare the kernels).
void ProjectBasisBatchAt(VectorLevel level, int lmax, std::size_t n, const double* x, const double* y,
                         const double* z, const double* wr, const double* wg, const double* wb, double* sums);

/// Y_k of n unit directions (x[i], y[i], z[i]) into out[i * CoeffCount(lmax) + k], several
/// directions per vector: what shading a vertex's lobe toward a moving eye needs for every
/// vertex of a frame. Each direction rounds as ProjectBasisBatch's do (EvalBasis rounds
/// differently), the same bits from the SSE2, AVX2 and AVX-512 kernels.
void EvalBasisBatch(int lmax, std::size_t n, const double* x, const double* y, const double* z, double* out);

/// EvalBasisBatch with the kernel of `level`, or of the widest level below it this CPU runs.
void EvalBasisBatchAt(VectorLevel level, int lmax, std::size_t n, const double* x, const double* y, const double* z,
                      double* out);

/// Closed forms of bands 0..2 (9 values), as listed in CONVENTIONS.md.
void EvalBasisBand2(const glm::dvec3& dir, double* out);

/// Slow reference for tests: long-double unnormalised Legendre recurrence, factorial
/// normalisation and cos/sin(m phi) from atan2. Independent of the fast path by construction.
long double EvalBasisReference(int l, int m, const glm::dvec3& dir);

}  // namespace prt
