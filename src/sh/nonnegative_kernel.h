#pragma once
/// \file
/// The sharpest non-negative zonal kernel of bands 0..lmax: the window that keeps every
/// non-negative light non-negative.
///
/// Windowing band l by w_l is convolving the light with the zonal kernel
///   K(x) = sum_l (2l+1)/(4 pi) w_l P_l(x),   x = cos(angle)            (Funk–Hecke)
/// so if K >= 0 on [-1, 1], a non-negative light stays non-negative whatever it is, a sun of
/// any strength included. Such kernels exist for every lmax; we take the one of greatest mean
/// cosine w_1 = int x K / int K (the least blurring by that measure). Every polynomial of degree
/// L that is non-negative on [-1, 1] is p^2 + (1 - x^2) q^2 (L even) or (1 + x) p^2 + (1 - x) q^2
/// (L odd) [1, 1.21], and w_1 is largest for the single term
///   K(x) = omega(x) p(x)^2,   omega = 1 (L even) or 1 + x (L odd),   deg p = n = floor(L/2),
/// where p maximises int x omega p^2 / int omega p^2: the Christoffel–Darboux kernel
/// p(x) = sum_{k<=n} q_k(x*) q_k(x) of the polynomials q_k orthonormal for omega, at the largest
/// zero x* of q_{n+1}, and then w_1 = x* [1, 3.41]. The q_k come from their three-term
/// recurrence (Stieltjes' procedure on a Gauss–Legendre rule exact for every product needed),
/// x* by Newton's method from x = 1, where it converges monotonically; the weights are the
/// Legendre moments int K P_l / int K on the same rule. w_1 measured: 0.333 (lmax 1), 0.577 (2),
/// 0.690 (3), 0.775 (4), 0.823 (5), 0.906 (8), 0.968 (16), 0.991 (32), 0.997 (64); against the
/// largest zeros in closed form in tests/sh/test_dering.cpp.
///
/// References
/// [1] Szegő, "Orthogonal Polynomials", AMS 1939: 1.21 (Lukács' representation of non-negative
///     polynomials), 3.2 (Christoffel–Darboux), 3.41 (the extremal property of the largest zero).
/// [2] Sloan, "Deringing Spherical Harmonics", 2017: windows chosen so the zonal kernel has no
///     negative lobe, found by minimising the kernel as a univariate polynomial.

#include <vector>

namespace prt {

/// w_0..w_lmax of the sharpest non-negative kernel above (w_0 = 1), lmax >= 0.
std::vector<double> NonNegativeKernelWeights(int lmax);

/// min over x in [-1, 1] of K(x) / K(1) for the weights w (a dense grid of 64 (lmax + 1)
/// points in angle; for tests and the report).
double KernelMinimumRatio(const std::vector<double>& w);

}  // namespace prt
