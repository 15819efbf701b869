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

}  // namespace prt
