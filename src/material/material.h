#pragma once
/// \file
/// The surface material of `--material` (CONVENTIONS: "Glossy transfer"):
///
///   diffuse      f(v, s) = albedo / pi
///   phong:N,KS   f(v, s) = albedo / pi + KS (N+2)/(2 pi) max(0, r.s)^N,  r = reflect(-v, n)
///
/// v points from the surface to the eye, s toward the light, r is the mirror of v about the
/// normal n. The outgoing radiance is B(v) = integral L(s) V(s) f(v, s) max(0, n.s) ds: the
/// cosine stays in the integral for both terms. The lobe integrates to 1 against max(0, r.s)
/// over the sphere, so at normal view (r = n) a white furnace gives exactly albedo + KS; at other
/// views the horizon cuts the lobe and it gives less. albedo + KS <= 1 keeps energy.

#include <string>

#include "material/lobe.h"

namespace prt {

struct Material {
  bool glossy = false;     ///< false: diffuse
  Lobe lobe;               ///< the Phong lobe (glossy only)
  double ks = 0.5;         ///< weight of the lobe (glossy only)

  /// "diffuse" or "phong:N,KS", what --material takes.
  std::string Name() const;
};

/// A glossy material of `lobe` weighted by `ks`.
Material GlossyMaterial(const Lobe& lobe, double ks);

/// Exponent range of phong:N.
constexpr int kMinPhongExponent = 1, kMaxPhongExponent = 1000;

/// Parses `diffuse` or `phong:N[,KS]` (N an integer 1..1000, KS in [0, 1], default 0.5). Throws
/// Error with the problem and what was expected when `text` is malformed.
Material ParseMaterial(const std::string& text);

/// Whether albedo + KS keeps energy for the largest albedo channel `max_albedo`:
/// max_albedo + ks <= 1 + 1e-6 (the slack for an albedo stored as float: 0.8f is 0.800000012).
/// CheckMaterialEnergy's test.
bool EnergyFits(double ks, double max_albedo);

/// Throws Error when albedo + KS exceeds 1 for the largest albedo channel `max_albedo` (the
/// surface would reflect more than it receives); `where` names the albedo's origin.
void CheckMaterialEnergy(const Material& material, double max_albedo, const std::string& where);

/// A KS to offer as `--material phong:N,KS`, with two decimals.
struct KsOffer {
  double ks = 0.0;       ///< a multiple of 0.01 (k / 100.0: the double that its two decimals parse to)
  bool lowered = false;  ///< true when the nearest did not fit beside the albedo
};

/// The KS to offer for a coat of weight `ks` (clamped to [0, 1]) beside the largest albedo
/// channel `max_albedo`: `ks` rounded to the nearest 0.01 when that fits (EnergyFits), else the
/// largest multiple of 0.01 that does, found by EnergyFits itself: the value offered, typed
/// back, is always accepted (a Ks of 0.3555 beside Kd 0.644 rounded to the nearest was offered
/// as 0.36, which CheckMaterialEnergy refuses: 1.004); 0 when none above 0 fits.
KsOffer FittingKs(double ks, double max_albedo);

/// The BRDF f(v, s) / albedo-free: the lobe's value KS h(r.s) (0 for diffuse), for r the
/// mirrored view direction.
double GlossyValue(const Material& material, double r_dot_s);

}  // namespace prt
