#pragma once
/// \file
/// The bounces of interreflected transport (transport.h has the maths): each gathers the previous
/// bounce's transfer at the hit points the direct pass recorded; its steps are also a farm job's
/// (bounce_stages.h, farm/assemble_bounces.h).

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
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

/// Sum of the band-0 coefficient over vertices and channels: a bounce's energy.
double BounceEnergy(const std::vector<double>& t, int count);

/// Bounce 0: the direct transfer of each of `vertices` (count coefficients each), the same for
/// every one of `channels`.
std::vector<double> BounceZero(const std::vector<double>& direct, std::size_t vertices, int channels, int count);

/// The hits of `block`'s vertices on the lit side of a surface: none, and no bounce has light.
std::uint64_t FrontHits(const std::vector<std::vector<VertexHit>>& hits, const VertexBlock& block);

/// One bounce at the vertices of `block`: into their rows of `next` (every vertex's size, zero
/// there), what each gathers of `current` (the bounce before, every vertex) at its `hits` (those
/// of the block's vertices at least). AddBounces runs it for every vertex, a farm task for its
/// block: the same operations in the same order at each vertex, so the same bits.
void BounceRows(const Mesh& mesh, const DirectionPlan& plan, const std::vector<std::vector<VertexHit>>& hits,
                const std::vector<double>& current, int channels, int count, const VertexBlock& block,
                std::vector<double>& next, const std::string& label);

/// Adds up to options.bounces bounces to `direct`; records each bounce's share in `report`.
/// None when none of the first `counted` vertices (the output's; the rest only send light,
/// bounce_senders.h) sees a lit surface: their bounces would all be zero.
BounceResult AddBounces(const Mesh& mesh, const DirectionPlan& plan, const DirectResult& direct,
                        const TransportOptions& options, TransportReport& report, bool keep_before_last = false,
                        std::size_t counted = std::numeric_limits<std::size_t>::max());

}  // namespace prt
