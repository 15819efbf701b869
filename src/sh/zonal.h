#pragma once
/// \file
/// The clamped cosine max(0, cos theta) as a zonal function, and what that gives diffuse transfer.
///
/// By the Funk–Hecke theorem, integrating L(w) max(0, n.w) over the sphere multiplies each band
/// of L by A_l [1]:
///   A_0 = pi, A_1 = 2 pi / 3, A_l = 0 for odd l > 1, and for even l
///   A_l = 2 pi (-1)^(l/2 - 1) / ((l + 2)(l - 1)) * l! / (2^l ((l/2)!)^2)
/// (A_2 = pi/4, A_4 = -pi/24, A_6 = pi/64). The factor l!/(2^l ((l/2)!)^2) = C(l, l/2) / 2^l is
/// accumulated as a running product, so no factorial is ever formed.
///
/// Unshadowed diffuse transfer is then exact in closed form: T_lm(n) = (A_l / pi) Y_lm(n),
/// the 1/pi of the Lambertian BRDF folded in, albedo applied separately (CONVENTIONS.md).
///
/// References
/// [1] Ramamoorthi, Hanrahan, "An Efficient Representation for Irradiance Environment Maps",
///     SIGGRAPH 2001; and "On the relationship between radiance and irradiance", JOSA A 2001.

#include <glm/vec3.hpp>

namespace prt {

/// A_l: the band-l multiplier of convolution with the clamped cosine (any l >= 0).
double ClampedCosineBand(int l);

/// SH projection of max(0, cos theta) about +Z, band l: sqrt((2l+1)/(4 pi)) * A_l ... divided
/// out: returns A_l / sqrt(4 pi / (2l+1)), e.g. 0.886227, 1.023327, 0.495416 for l = 0, 1, 2.
double ClampedCosineZonalCoeff(int l);

/// Unshadowed diffuse transfer of a vertex with unit normal n: T_k = (A_l/pi) Y_k(n),
/// k < CoeffCount(lmax), written to out.
void UnshadowedTransfer(int lmax, const glm::dvec3& n, double* out);

}  // namespace prt
