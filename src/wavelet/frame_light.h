#pragma once
/// \file
/// Haar wavelets as a basis of the frame loop (basis/frame_light.h). A frame:
///
///   light     the environment turned by the frame's rotation and resampled onto the cube, each
///             texel its mean radiance (light_cube.h), taken to Haar coefficients; optionally only
///             the K most important kept (Ng's non-linear approximation, selection.h);
///   shading   each vertex a sparse dot product of its kept transport coefficients with that
///             light, plus its bounces through the SH light turned by the band rotations (shade.h);
///   kept      the kept light back on the texels (the light view).
///
/// The transport view shows SH coefficients, which this basis has none of to show.

#include <memory>

#include <glm/vec3.hpp>

#include "basis/frame_light.h"
#include "env/environment.h"
#include "sh/coeffs.h"
#include "wavelet/selection.h"
#include "wavelet/transport.h"

namespace prt {

/// The light cube's cells a texel along each side at interactive quality (basis/frame_light.h),
/// against LightCube::kFineCells at still quality. The energy is kept exactly at any count; a
/// frame's light costs about the square of the count. Measured (Intel Xeon, AVX-512, 2 vCPUs; the
/// demo scene, F 32, 640x480 at ssaa 1 in prt view, median of 20 frames, with the light shared
/// by tents, before wavelet/texel_lerp.h, whose Resample costs 20 % more at 8 cells and the same
/// at 2): a frame's draw 27 ms at 8 cells, 15 ms at 2. A sphere's shading under the sky differs
/// from the still light's by 0.0036 % RMS at F 16 (tests/wavelet/test_frame_light.cpp); a sun
/// smaller than a cell flickers by at most 0.046 % a step in a slow turn against 0.036 % at still
/// quality (tests/wavelet/test_light_cube_sun.cpp).
inline constexpr int kInteractiveCells = 2;

/// Wavelets: `transport` under `env` turned about `axis`, `sh_light` lighting its bounces (may
/// be empty without them); `light_terms` > 0 keeps only that many light coefficients per frame,
/// chosen by `selection`; the environment gathered into `cells` x `cells` cells a texel
/// (LightCube; 0: its default). `env` and `transport` must outlive the result.
std::unique_ptr<FrameLight> MakeWaveletFrameLight(const WaveletTransport& transport, const Environment& env,
                                                  const ShRgb& sh_light, const glm::dvec3& axis, int light_terms,
                                                  Selection selection, int cells = 0);

}  // namespace prt
