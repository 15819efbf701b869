#pragma once
/// \file
/// Built-in environments that need no file.
///
/// `furnace[:C]`: constant radiance C (default 1) from every direction. The white-furnace test of
///   every renderer: L_00 = 2 sqrt(pi) C, all other coefficients 0, and a diffuse surface of
///   albedo rho reflects exactly rho C.
/// `sky[:key=value,...]`: an HDR daylight sky: blue zenith fading to a bright horizon, a dim
///   ground below, a soft glow around the sun and the sun itself, a disk of angular radius
///   `radius` degrees whose irradiance at normal incidence is `sun` (the sky's own irradiance on
///   an upward surface is about 2). Keys: sun (default 3), elevation (degrees above the horizon,
///   default 40), azimuth (degrees from -Z towards +X, default 35), radius (default 2).
///
/// Both are integrated by a Gauss product rule with its polar axis on world up (exact for
/// smooth, band-limited radiance to spectral accuracy). The sun disk, which no such grid
/// resolves, is projected analytically: a cap of half-angle a with radiance E around unit s has
///   c_lm = 2 pi E I_l Y_lm(s),  I_l = integral_{cos a}^1 P_l(t) dt
///        = (P_{l-1}(cos a) - P_{l+1}(cos a)) / (2l + 1)   (I_0 = 1 - cos a),
/// the Funk–Hecke theorem applied to the cap's indicator [1].
///
/// References
/// [1] Sloan, "Stupid Spherical Harmonics (SH) Tricks", GDC 2008, zonal harmonics of a cone.

#include <memory>
#include <string>

#include "env/environment.h"

namespace prt {

struct SkyParams {
  double sun = 3.0;         ///< sun irradiance at normal incidence
  double elevation = 40.0;  ///< degrees above the horizon
  double azimuth = 35.0;    ///< degrees from -Z towards +X
  double radius = 2.0;      ///< angular radius of the disk, degrees
};

/// Constant radiance `c` everywhere.
std::unique_ptr<Environment> MakeFurnace(double c);

/// The daylight sky described above.
std::unique_ptr<Environment> MakeSky(const SkyParams& params);

/// Unit direction towards the sun of `params`.
glm::dvec3 SunDirection(const SkyParams& params);

/// Zonal integrals I_l = integral_{x}^{1} P_l(t) dt for l = 0..lmax (x = cos of the half-angle).
std::vector<double> CapLegendreIntegrals(int lmax, double x);

}  // namespace prt
