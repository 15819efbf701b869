#pragma once
/// \file
/// The stability cases about awkward inputs (see stability.h):
///   - extreme meshes: zero-area, sliver and duplicated triangles, vertex normals exactly on the
///     axes and grazing ones: every transport value finite, and within the bounds any diffuse
///     transfer obeys (0 <= T_00 <= Y_00, the unshadowed value);
///   - albedo 0.99 in a deep open well under constant light, 64 bounces: the series converges and
///     respects the energy bound of a furnace, radiance <= albedo (incoming radiance never
///     exceeds 1 anywhere, so reflected radiance never exceeds albedo * 1) [1];
///   - NaN, +-Inf, negative and 1e30 texels: sanitised, and no NaN reaches the light coefficients;
///   - a Phong lobe of N = 1000 at lmax 2, far sharper than the bands, on the knot and plane under
///     the HDR sun, both glossy paths: no value that is not finite, no vertex darker than the
///     bands imply, and the run-summary warning that lmax 2 keeps too little of the lobe
///     (GlossySharpLobe below says what "darker than the bands imply" means).
///
/// References
/// [1] Kajiya, "The Rendering Equation", SIGGRAPH 1986 (the Neumann series converges for albedo < 1).

#include <vector>

#include "basis/stability_case.h"

namespace prt {

void ExtremeMeshes(std::vector<StabilityCase>& out);
void DeepConcavity(std::vector<StabilityCase>& out);
void BadTexels(std::vector<StabilityCase>& out);

/// glossy_n1000_lmax2. The light is the HDR sun windowed by --window auto, so its band-limited
/// reconstruction L is non-negative everywhere; f(s) = L(s) V(s) max(0, n.s) is then non-negative
/// and integrates to the vertex's irradiance E = pi (L.T). Each path's radiance is an integral of
/// f against a kernel about the mirror direction r:
///   vector    B = integral f(s) (albedo/pi + KS h(r.s)) ds >= albedo (L.T), h the lobe (>= 0);
///   matrices  B = integral f(s) (albedo/pi + KS K(r.s)) ds >= albedo (L.T) + KS min(K) E,
///             K(mu) = sum_{l<=lmax} h_l (2l+1)/(4 pi) P_l(mu) the lobe truncated to the bands,
///             whose ringing (min K < 0) is what the bands imply: a sharp lobe at lmax 2 is a
///             broad kernel with a negative ring, which can make a dark vertex's radiance negative.
/// A vertex counts as a violation when its radiance is below its bound by more than the Monte
/// Carlo noise allowance (the estimates are unbiased, not bounded). The case also fails when
/// LobeBandShare(N = 1000, lmax 2) is not below the warning's 90%.
void GlossySharpLobe(std::vector<StabilityCase>& out);

}  // namespace prt
