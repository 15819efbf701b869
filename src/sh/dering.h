#pragma once
/// \file
/// `--window auto`: per light, the least blurring window of a one-parameter family that makes
/// the reconstruction non-negative in every direction.
///
/// The family blends no window with the sharpest non-negative kernel k_l
/// (sh/nonnegative_kernel.h):
///   w_l(t) = (1 - t) + t k'_l,   k'_l = (1 - 1e-6) k_l for l >= 1, t in [0, 1],
/// where the 1e-6 of a constant kernel added to k makes it strictly positive, so rounding can
/// never leave t = 1 a hair below zero. The windowed reconstruction is linear in t:
///   f_t(d) = (1 - t) A(d) + t B(d),   A = no window, B = the kernel's,
/// and B >= 0 for any non-negative light (a non-negative kernel convolved with it). So f_t(d) >= 0
/// exactly when t >= -A(d) / (B(d) - A(d)) wherever A(d) < 0, and the least t is the largest
/// such ratio over the sphere and the three channels: a search for one maximum, not a
/// bisection. It is found on a Gauss grid of ceil(1.5 lmax) + 12 latitudes, refined from the 16
/// best grid points by a compass search on the sphere, and taken with a margin of 1e-6 in t.
/// The result is then checked the same way for its lowest value; if that is still negative (a
/// dip the grid missed), t moves halfway to 1 and is checked again. t = 1 always succeeds for
/// a non-negative light, so the search never gives up. Anchor: Sloan [1] chooses a window so
/// the zonal kernel has no negative lobe, conservatively for every light; here the kernel is
/// that conservative end, and t spends only as much of it as this light needs.
///
/// Cost reported: the added relative RMS error of the irradiance (Funk–Hecke: band l of the
/// irradiance is A_l L_l, sh/zonal.h; Parseval) against the unwindowed light,
///   sqrt(sum_l A_l^2 (1 - w_l)^2 |L_l|^2 / sum_l A_l^2 |L_l|^2).
///
/// References
/// [1] Sloan, "Deringing Spherical Harmonics", SIGGRAPH Asia 2017 Technical Briefs.

#include <string>
#include <vector>

#include "sh/coeffs.h"
#include "sh/window.h"

namespace prt {

/// The highest lmax `--window auto` is offered for.
constexpr int kMaxAutoWindowLmax = 64;

struct AutoWindow {
  double t = 0;                  ///< strength in the family above; 0 = no window
  std::vector<double> weights;   ///< w_0..w_lmax (ApplyWeights, sh/window.h)
  double min_before = 0;         ///< lowest reconstructed radiance, any channel, no window
  double min_after = 0;          ///< the same with the window
  double peak = 0;               ///< highest reconstructed radiance without a window
  double irradiance_cost = 0;    ///< added relative RMS irradiance error (above)
  /// One clause for the run summary: the window, lowest radiance before and after, its cost.
  std::string Describe() const;
};

/// The window above for `coeffs` (bands 0..lmax, 0 <= lmax <= kMaxAutoWindowLmax).
AutoWindow ChooseAutoWindow(const ShRgb& coeffs);

/// Lowest value of any channel of sum_k c_k Y_k over the sphere: the grid and compass search
/// above. Stands apart from ChooseAutoWindow's own pass for reports.
double LowestRadiance(const ShRgb& coeffs);

}  // namespace prt
