#pragma once
/// \file
/// Shading with wavelet transport (transport.h): the outgoing radiance of vertex v is
///
///   albedo(v) * ( sum over v's kept k of L^_k T^_k(v)   +   sum_j L_j B_j(v) )
///
/// per colour channel: the direct light a sparse dot product with the frame's light in the Haar
/// basis (wavelet/light_cube.h), the bounced light B (SH, with interreflection) a dot product
/// with the frame's SH light, as precompute/shade.h does.

#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "geometry/mesh.h"
#include "wavelet/transport.h"
#include "sh/coeffs.h"
#include "wavelet/light_cube.h"
#include "wavelet/texel_sh.h"

namespace prt {

/// A frame's light in the Haar basis, packed for the dot products: coefficient k's R, G, B (and
/// a zero) at rgb[k]; for a transport with an SH base, the light's l_j (texel_sh.h) at sh[j].
struct WaveletLight {
  std::vector<glm::vec4> rgb;
  std::vector<glm::vec4> sh;
};

/// The l_j of the texel means `texels` (TexelSh::OfLight), per channel.
std::vector<glm::vec4> BaseLight(const TexelSh& base, const CubeRgb& texels);

/// Packs Haar coefficients (CubeToHaar's output) and the base's light `sh` for ShadeWavelet.
WaveletLight PackWaveletLight(const CubeRgb& coeffs, std::vector<glm::vec4> sh = {});

/// A frame's light: `cube`'s environment turned by `turn`, in the Haar basis, cut to its
/// `light_terms` most important coefficients by `weights` (0: all kept), with the l_j of what
/// is kept for `base` (nullptr: a transport without one); the coefficients also in `coeffs`.
WaveletLight TurnedWaveletLight(const LightCube& cube, const glm::dmat3& turn, int light_terms,
                                const std::vector<double>& weights, const TexelSh* base, CubeRgb& coeffs);

/// Linear RGB radiance of every vertex (without `albedo`: as if every albedo were 1): the
/// direct light from `light`, the bounced light from `sh_light` (bands beyond the bounce
/// transport's are not used).
std::vector<glm::vec3> ShadeWavelet(const Mesh& mesh, const WaveletTransport& transport, const WaveletLight& light,
                                    const ShRgb& sh_light, bool albedo = true);

/// Direct radiance (albedo 1, RGB and a zero) of vertex v's SH base and kept coefficients under
/// `light`.
glm::vec4 DirectLight(const WaveletTransport& transport, std::size_t v, const WaveletLight& light);
/// The SH base's part of it alone (0 without a base).
glm::vec4 BaseDirectLight(const WaveletTransport& transport, std::size_t v, const WaveletLight& light);

/// Direct radiance (albedo 1) of one vertex's full coefficient vector `coeffs` (6 F^2 entries, a
/// probe's unkept wavelet part) under `light`.
glm::vec3 ShadeDense(const float* coeffs, const WaveletLight& light);

}  // namespace prt
