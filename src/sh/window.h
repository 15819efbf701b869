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
/// Band 0 is never changed, so total energy (the average radiance) is preserved. Neither of these
/// keeps a bright sun non-negative at every lmax; `--window auto` does (sh/dering.h).
///
/// References
/// [1] Sloan, "Stupid Spherical Harmonics (SH) Tricks", GDC 2008, section on windowing.
/// [2] Hanson, "Stupid Spherical Harmonics" notes; Lanczos sigma factors (Lanczos 1956).

#include <string>
#include <vector>

#include "sh/coeffs.h"

namespace prt {

enum class Window { kNone, kHann, kLanczos };

/// "none", "hann" or "lanczos".
const char* WindowName(Window w);
/// Every window's name, in the enum's order (`--window` takes these and "auto", sh/dering.h).
std::vector<std::string> WindowNames();

/// The weight w_l of band l for a truncation at lmax.
double WindowWeight(Window w, int l, int lmax);

/// "none", "hann" or "lanczos" as a Window; throws Error for any other name.
Window WindowFromName(const std::string& name);

/// Multiplies each band l of `coeffs` by weights[l] (weights of at least its bands).
void ApplyWeights(const std::vector<double>& weights, ShRgb& coeffs);

/// Multiplies each band of `coeffs` (of bands 0..lmax) by its weight.
void ApplyWindow(Window w, ShRgb& coeffs);

}  // namespace prt
