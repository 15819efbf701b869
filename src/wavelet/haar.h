#pragma once
/// \file
/// The 2-D Haar wavelet basis on an n x n image (n a power of two), orthonormal, in the
/// non-standard decomposition [1, sec. 3.2; 2, sec. 3]: one level is one averaging-and-
/// differencing step on every row, then one on every column, of the n' x n' block of averages
/// left by the level before (n' = n, n/2, ..., 2). One step on a pair (a, b) is
///
///   s = (a + b) / sqrt(2),   d = (a - b) / sqrt(2),
///
/// the averages s in the first half, the differences d in the second. Every step is a rotation
/// by 45 degrees of each pair, so the whole transform is orthonormal: the inverse is its
/// transpose, and sums of products (a light times a transport) are the same in either basis
/// (Parseval), which is what makes the frame's radiance a sparse dot product [3].
///
/// Layout after the transform: entry (0, 0) is the scaling coefficient (the image's sum / n);
/// for level l = 0, 1, ..., log2(n) - 1, the details of that level fill the three blocks
/// [2^l, 2^(l+1)) x [0, 2^l), [0, 2^l) x [2^l, 2^(l+1)) and [2^l, 2^(l+1))^2 (row x column), each
/// detail covering a square of (n / 2^l)^2 texels of the image (HaarSupport).
///
/// References
/// [1] Stollnitz, DeRose, Salesin, "Wavelets for Computer Graphics: A Primer, Part 1", IEEE CG&A
///     15(3), 1995 (the 1-D Haar steps, normalised).
/// [2] Stollnitz, DeRose, Salesin, "... Part 2", IEEE CG&A 15(4), 1995 (standard and non-standard
///     2-D decompositions).
/// [3] Ng, Ramamoorthi, Hanrahan, "All-Frequency Shadows Using Non-linear Wavelet Lighting
///     Approximation", SIGGRAPH 2003.

#include <vector>

namespace prt {

/// Transforms the n x n image at `data` (row-major) into Haar coefficients, in place. `scratch`
/// is resized to n. n must be a power of two >= 1.
void HaarForward(double* data, int n, std::vector<double>& scratch);

/// The inverse of HaarForward, in place.
void HaarInverse(double* data, int n, std::vector<double>& scratch);

/// Side, in texels, of the square of the image that coefficient (row, col) of an n x n
/// transform covers: n for the scaling coefficient and the coarsest details, n / 2^l for the
/// details of level l.
int HaarSupport(int row, int col, int n);

}  // namespace prt
