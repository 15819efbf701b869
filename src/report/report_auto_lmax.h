#pragma once
/// \file
/// `--lmax auto --tolerance X`: the smallest band count whose measured error is below X.
///
/// Diffuse transport sees the light only through the clamped cosine: by the Funk–Hecke
/// theorem the irradiance has coefficients E_lm = A_l L_lm (sh/zonal.h) [1]. The error of
/// truncating it after band L, relative to a reference of kAutoReferenceLmax bands, is by
/// Parseval's theorem exactly
///   e(L) = sqrt( sum_{L < l <= ref} A_l^2 |L_lm|^2 / sum_{l <= ref} A_l^2 |L_lm|^2 )
/// (summed over R, G, B): the relative L2 error over the sphere of the reconstructed irradiance.
/// A_l = 0 for odd l > 1, so the choice is 0, 1 or even. The light is projected once at the
/// reference lmax (the projection of bands 0..L is a prefix of it).
///
/// References
/// [1] Ramamoorthi, Hanrahan, "An Efficient Representation for Irradiance Environment Maps",
///     SIGGRAPH 2001 (A_l decays as l^-5/2: a few bands hold almost all the irradiance).

#include <string>

#include "env/environment.h"

namespace prt {

/// Bands of the reference against which e(L) is measured.
constexpr int kAutoReferenceLmax = 32;

struct AutoLmax {
  int lmax = 0;
  double error = 0;  ///< e(lmax)
  std::string why;   ///< one line for the run summary
};

/// The smallest lmax in [0, max_lmax] with e(lmax) <= tolerance (max_lmax if none is).
AutoLmax ChooseLmax(const Environment& env, double tolerance, int max_lmax);

}  // namespace prt
