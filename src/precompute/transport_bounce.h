#pragma once
/// \file
/// The bounces of interreflected transport (transport.h has the maths): each gathers the previous
/// bounce's transfer at the hit points the direct pass recorded. Internal to precompute/.

#include <cstddef>
#include <limits>
#include <vector>

#include "geometry/mesh.h"
#include "precompute/direction_pool.h"
#include "precompute/transport_direct.h"
#include "precompute/transport_types.h"

namespace prt {

struct BounceResult {
  int channels = 1;
  std::vector<double> transfer;  ///< [(v * channels + c) * count + k], direct + all bounces
  /// The same without the last bounce computed (what a glossy receiver gathers from a diffuse
  /// hit point: its light through bounce B - 1); filled only when asked for.
  std::vector<double> before_last;
};

/// Adds up to options.bounces bounces to `direct`; records each bounce's share in `report`.
/// None when none of the first `counted` vertices (the output's; the rest only send light,
/// bounce_senders.h) sees a lit surface: their bounces would all be zero.
BounceResult AddBounces(const Mesh& mesh, const DirectionPlan& plan, const DirectResult& direct,
                        const TransportOptions& options, TransportReport& report, bool keep_before_last = false,
                        std::size_t counted = std::numeric_limits<std::size_t>::max());

}  // namespace prt
