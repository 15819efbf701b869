#pragma once
/// \file
/// The pool of direction sets the shadowed and interreflected transport draw from: each set
/// is drawn once by the sampler from its own random stream and prepared once as a ray fan.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/ray_fan.h"
#include "precompute/samplers.h"

namespace prt {

struct DirectionPool {
  std::vector<std::vector<glm::dvec3>> sets;  ///< unit directions, double precision
  std::vector<RayFan> fans;                   ///< the same directions, packed for tracing
  std::uint64_t seed = 0;

  /// The set vertex `v` uses: a hash of (seed, v), so neighbours differ.
  std::size_t SetOf(std::size_t v) const;
  /// Directions per set (all sets have the same size).
  std::size_t size() const { return sets.empty() ? 0 : sets[0].size(); }
};

/// `count` sets of `samples` directions drawn by `sampler` from streams (seed, 0..count-1).
DirectionPool MakeDirectionPool(Sampler sampler, int samples, int count, std::uint64_t seed);

/// The pools of one transport and the one each vertex draws from: pool 0 (`samples`
/// directions) for the vertices the camera sees, pool 1 (`hidden_samples`) for the others, when
/// there are any and the counts differ (precompute/sample_rule.h says why).
struct DirectionPlan {
  std::vector<DirectionPool> pools;
  std::vector<std::uint8_t> pool_of;  ///< per vertex: index into pools (empty: pool 0 for all)

  const DirectionPool& PoolOf(std::size_t v) const { return pools[pool_of.empty() ? 0 : pool_of[v]]; }
  /// Direction i of the set vertex v draws.
  const glm::dvec3& Direction(std::size_t v, std::uint32_t i) const {
    const DirectionPool& pool = PoolOf(v);
    return pool.sets[pool.SetOf(v)][i];
  }
};

/// The plan for `vertices` vertices: `seen` (per vertex, nonzero: the camera sees it; empty:
/// every vertex) take `samples` directions, the others `hidden_samples`. Pool 0 is
/// MakeDirectionPool(sampler, samples, count, seed), so a plan without hidden vertices draws
/// what a single pool would; pool 1 draws from the seed mixed with 1.
DirectionPlan MakeDirectionPlan(Sampler sampler, int samples, int hidden_samples, int count, std::uint64_t seed,
                                const std::vector<std::uint8_t>& seen, std::size_t vertices);

}  // namespace prt
