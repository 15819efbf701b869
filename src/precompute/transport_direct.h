#pragma once
/// \file
/// The direct pass of shadowed transport (transport.h has the maths): per vertex the closed form
/// minus the Monte Carlo estimate of what its rays find blocked, and, for the passes after it,
/// what each blocked ray hit. Internal to precompute/.

#include <cstdint>
#include <vector>

#include "geometry/bvh.h"
#include "geometry/mesh.h"
#include "precompute/direction_pool.h"
#include "precompute/hit_light.h"
#include "precompute/transport_types.h"

namespace prt {

struct DirectResult {
  std::vector<double> transfer;                ///< [v * count + k]
  std::vector<std::vector<VertexHit>> hits;    ///< per vertex (only when asked for)
  std::vector<std::uint8_t> sees_sky;          ///< per vertex: some direction above it is open
  std::vector<std::uint8_t> unoccluded;        ///< per vertex: nothing blocked (the closed form)
  std::uint64_t rays = 0;
  /// Directions whose basis was evaluated ((lmax+1)^2 values each): the blocked ones, or a
  /// whole set at once where its table is built.
  std::uint64_t basis_evaluations = 0;
};

/// Shadowed transfer of every vertex (control-variate estimator), each from the set of its pool
/// in `plan`. With `keep_hits`, traces closest hits instead of any-hit rays and records them
/// (VertexHit::dir indexes the vertex's set). Only the vertices of `block` are computed; the
/// others are left 0 (and unoccluded 0, sees_sky 0, no hits).
DirectResult ComputeDirect(const Mesh& mesh, const Bvh& bvh, const DirectionPlan& plan, int lmax, bool keep_hits,
                           const VertexBlock& block = {});

}  // namespace prt
