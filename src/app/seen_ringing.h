#pragma once
/// \file
/// Whether the frames of a render would show the light's SH ringing: the rule behind the
/// default window of `render` and `demo` (`--window` not given: auto where the frames would
/// show ringing, none elsewhere).
///
/// A frame does not show the light L itself but what the surface makes of it, a convolution of
/// L with a zonal kernel (sh/convolved_range.h: band l scaled by the kernel's k_l):
///   --view radiance     the diffuse part, the irradiance A * L (A_l, sh/zonal.h), and with a
///                       glossy material the lobe's part, the light seen through the lobe h * L
///                       (the Phong lobe's h_l, material/lobe.h)
///   --view irradiance   A * L
///   --view glossy       h * L (a glossy material; nothing otherwise)
///   --view light        L itself
///   --view albedo, transport: no light.
/// The clamped cosine is a wide low-pass kernel: a sun that makes L ring often leaves A * L
/// non-negative (the built-in sky at lmax 4: L goes down to -11% of its peak, A * L not below
/// 0). A Phong lobe of exponent N keeps bands up to about sqrt(N), so a glossy coat shows nearly
/// the light's own ringing (phong:50 there: -8.8%, blotches on the ground under a glossy knot).
/// Shadows and bounces change what each vertex integrates; the
/// unshadowed convolutions above are the light's share of what the frames show. Negative pixels
/// the transport makes itself (the transfer matrices of a glossy --orbit, sampled shadows) are
/// another matter, which no window of the light removes (the ringing note says which).
///
/// Each shown convolution "rings" when its lowest value is below -kSeenRingingTolerance times
/// its peak. Then the auto window (sh/dering.h) makes L non-negative everywhere, and with it
/// every shown convolution (a non-negative kernel convolved with a non-negative light).

#include <string>
#include <vector>

#include "material/material.h"
#include "render/render_options.h"
#include "sh/coeffs.h"

namespace prt {

/// How far below zero, as a share of its peak, a shown convolution may go and still count as
/// non-negative. A light that is exactly 0 somewhere (a black ground, a channel of 0) comes out
/// of the projection's sums and the basis evaluations at rounding level there, around 1e-15 of
/// its peak, which is no ringing; ringing of a sharp light is percents (above). 1e-6 lies
/// between, and below what a frame can show: the smallest non-zero 8-bit sRGB level is
/// 1/(255 x 12.92) = 3e-4 of white.
constexpr double kSeenRingingTolerance = 1e-6;

/// One convolution of the light that frames show.
struct ShownLight {
  std::string name;            ///< for the run summary: "the irradiance", "the light seen through the glossy lobe", "the light"
  std::vector<double> kernel;  ///< its zonal coefficients k_0..k_lmax
};

/// The convolutions of the light that frames of `view` ("radiance", "irradiance", "glossy",
/// "light", "albedo", "transport") show with `material`, at bands 0..lmax (table above).
std::vector<ShownLight> ShownLights(const Material& material, View view, int lmax);

/// The shown convolution that goes lowest relative to its peak, and whether it rings.
struct SeenRinging {
  bool rings = false;  ///< its lowest value is below -kSeenRingingTolerance times its peak
  std::string what;    ///< its ShownLight::name; empty when the view shows no light
  double lowest = 0;   ///< its lowest value, any channel, over the sphere
  double peak = 0;     ///< its highest value
};

/// Whether frames of `view` with `material` would show the ringing of `light` (bands 0..lmax).
SeenRinging FindSeenRinging(const ShRgb& light, const Material& material, View view);

}  // namespace prt
