#pragma once
/// \file
/// Windowing (band-limiting) of SH coefficients against ringing.
///
/// Truncating a function with sharp features to bands 0..lmax rings like a Fourier series
/// (Gibbs): a bright sun turns into negative lobes elsewhere. Multiplying band l by a window
/// w_l that falls smoothly to 0 at lmax + 1 trades sharpness for less ringing [1, 2]:
///   none:    w_l = 1
///   hann:    w_l = (1 + cos(pi l / (lmax + 1))) / 2
///   lanczos: w_l = sinc(pi l / (lmax + 1)) = sin(x)/x     (w_0 = 1)
/// Band 0 is never changed, so total energy (the average radiance) is preserved.
///
/// References
/// [1] Sloan, "Stupid Spherical Harmonics (SH) Tricks", GDC 2008, section on windowing.
/// [2] Hanson, "Stupid Spherical Harmonics" notes; Lanczos sigma factors (Lanczos 1956).

#include <string>

#include "sh/coeffs.h"

namespace prt {

enum class Window { kNone, kHann, kLanczos };

/// "none", "hann" or "lanczos".
const char* WindowName(Window w);

/// The weight w_l of band l for a truncation at lmax.
double WindowWeight(Window w, int l, int lmax);

/// Multiplies each band of `coeffs` (of bands 0..lmax) by its weight.
void ApplyWindow(Window w, ShRgb& coeffs);

}  // namespace prt

namespace prt {

/// The result of `--window auto`.
struct AutoWindow {
  Window window;
  double min_before;  ///< lowest reconstructed radiance (any channel) without a window
  double min_after;   ///< the same with the chosen window
};

/// The mildest window (none, then lanczos, then hann) whose reconstruction of `coeffs` is
/// non-negative everywhere, checked on a Gauss grid fine enough for bands 0..lmax; hann if
/// none is (it rings least). Negative values relative to the mean radiance below 1e-9 count as
/// zero, so rounding never forces a window.
AutoWindow ChooseWindow(const ShRgb& coeffs);

/// Lowest value of any channel of the reconstruction sum_k c_k Y_k over the sphere (sampled on
/// a Gauss grid of lmax + 8 latitudes, exact for band-limited products of this size).
double MinReconstruction(const ShRgb& coeffs);

}  // namespace prt
