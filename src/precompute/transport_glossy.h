#pragma once
/// \file
/// The glossy pass (transport.h has the maths): a glossy material's transfer vector toward the
/// fixed eye, the lobe's unshadowed transfer minus what rays drawn from the lobe find blocked,
/// plus the light of diffuse hit points. Internal to precompute/.

#include <vector>

#include "geometry/bvh.h"
#include "geometry/mesh.h"
#include "precompute/transport_types.h"

namespace prt {

/// The glossy transfer G of every vertex (transport.h) for options.material seen from
/// options.eye; `hit_transfer` (layout of BounceResult::transfer with `channels`) is what hit
/// points send out with interreflection, null otherwise. Null `bvh`: unshadowed.
std::vector<double> ComputeGlossy(const Mesh& mesh, const Bvh* bvh, const TransportOptions& options,
                                  const std::vector<double>* hit_transfer, int channels, TransportReport& report);

}  // namespace prt
