#pragma once
/// \file
/// The sharpest non-negative zonal kernel of bands 0..lmax: the window that keeps every
/// non-negative light non-negative.
///
/// Windowing band l by w_l is convolving the light with the zonal kernel
///   K(x) = sum_l (2l+1)/(4 pi) w_l P_l(x),   x = cos(angle)            (Funk–Hecke)
/// so if K >= 0 on [-1, 1], a non-negative light stays non-negative whatever it is, a sun of
/// any strength included. Such kernels exist for every lmax; among them we take the one of
/// greatest mean cosine w_1 (the least blurring by that measure), from two classical families:
///   - a square: K = p(x)^2 with p of degree n = floor(lmax/2). The p maximising
///     w_1 = int x p^2 / int p^2 is the Christoffel–Darboux kernel at the largest zero x* of
///     P_{n+1}, p(x) = sum_{l<=n} (2l+1) P_l(x*) P_l(x), and then w_1 = x* [1, 2];
///   - the power of the cosine ((1 + x)/2)^lmax, w_l = lmax! (lmax+1)! / ((lmax-l)! (lmax+l+1)!),
///     w_1 = lmax / (lmax + 2): the better one at lmax 1 (1/3 against 0) and 3 (0.6 against 0.577).
/// The weights of the square are its Legendre moments, int K P_l / int K, by a Gauss–Legendre
/// rule exact for their degree. w_1 measured: 0.333 (lmax 1), 0.577 (2), 0.600 (3), 0.775 (4
/// and 5), 0.906 (8), 0.968 (16), 0.991 (32), 0.997 (64); the kernel's minimum is 0 to rounding
/// (|K_min / K(1)| < 3e-16) at each.
///
/// References
/// [1] Szegő, "Orthogonal Polynomials", AMS 1939, 3.2 (Christoffel–Darboux) and 3.41 (the
///     extremal property of the largest zero).
/// [2] Sloan, "Deringing Spherical Harmonics", 2017: windows chosen so the zonal kernel has no
///     negative lobe, found by minimising the kernel as a univariate polynomial.

#include <vector>

namespace prt {

/// w_0..w_lmax of the sharpest non-negative kernel above (w_0 = 1), 0 <= lmax <= 64.
std::vector<double> NonNegativeKernelWeights(int lmax);

/// min over x in [-1, 1] of K(x) / K(1) for the weights w (a dense grid of 64 (lmax + 1)
/// points in angle; for tests and the report).
double KernelMinimumRatio(const std::vector<double>& w);

}  // namespace prt
