#pragma once
/// \file
/// The wavelet transport of a scene as `render` and `demo` compute it, said on the run summary:
/// the cube, the rays, the budget and what was kept, the bytes, what the truncation costs under
/// the scene's light (frame 0's direct light at a sample of vertices, kept against every
/// coefficient), and with interreflection its bounces in SH.

#include <cstdint>
#include <vector>

#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "wavelet/options.h"
#include "wavelet/transport.h"

namespace prt {

/// ComputeWaveletTransport(mesh, sh, options) with its run-summary lines; `env` is the light the
/// truncation cost is measured under. Not cached here: app/scene_wavelets.cpp (SceneWavelets) reads
/// and writes wavelet/transport_cache.h around it.
WaveletTransport ComputeSceneWavelets(const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& options,
                                      const Environment& env);

}  // namespace prt
