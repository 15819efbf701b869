#pragma once
/// \file
/// The wavelet transport of a scene as the commands use it.

#include "basis/cache_plan.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "wavelet/options.h"
#include "wavelet/transport.h"

namespace prt {

/// The wavelet transport of `mesh` in the basis `wavelet` (wavelet_basis.h; wavelet/transport.h) for the transport options `sh` and the
/// wavelet options `w`: read from the cache (wavelet/transport_cache.h) when that file was made
/// from the same mesh and options, or from every vertex computed as a seen one when only the
/// seen vertices were asked for; else ComputeSceneWavelets (wavelet/summary.h, `env` the light its
/// truncation cost is measured under), written there when the plan allows (a failed write is a
/// warning). Said on the run summary.
WaveletTransport SceneWavelets(const Basis& wavelet, const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& w,
                               const Environment& env, const CachePlan& cache);

}  // namespace prt
