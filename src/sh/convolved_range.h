#pragma once
/// \file
/// The range of a light convolved with a zonal kernel: what a surface that integrates the light
/// against that kernel can show of it, negative values (ringing) included.
///
/// A kernel k(r.s) symmetric about its axis r has zonal coefficients k_l, and by the
/// Funk–Hecke theorem convolving it with a light of SH coefficients L_lm gives
///   (k * L)(r) = sum_lm k_l L_lm Y_lm(r):
/// each band l of the light scaled by k_l. The clamped cosine's k_l = A_l gives the irradiance
/// (sh/zonal.h), a Phong lobe's h_l the light seen through the lobe (material/lobe.h), k_l = 1
/// the light itself. The lowest value over the sphere and the three channels is LowestRadiance's
/// grid and compass search (sh/dering.h); the highest is minus the lowest of -(k * L), the same
/// search on the negated coefficients.

#include <vector>

#include "sh/coeffs.h"

namespace prt {

/// The lowest and highest value of any channel over the sphere.
struct ShRange {
  double lowest = 0;
  double highest = 0;
};

/// The range of sum_lm kernel[l] L_lm Y_lm over the sphere for `light` (bands 0..lmax) and
/// `kernel` (at least lmax + 1 zonal coefficients; only the ratios matter for signs).
ShRange ConvolvedRange(const ShRgb& light, const std::vector<double>& kernel);

}  // namespace prt
