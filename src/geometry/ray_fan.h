#pragma once
/// \file
/// A fixed set of directions prepared for tracing from many origins: the PRT workload, where
/// every vertex casts the same direction set (the part above its horizon) from its own position.
///
/// Everything per direction that traversal needs (the inverse for the slab test, the axis
/// permutation and shear of the watertight triangle test [1]) is computed here once instead of
/// once per ray. The rays are kept in an order that keeps successive directions close: by the
/// cube face the direction goes through, then in Morton order of its position on that face, so
/// consecutive directions make coherent packets (bvh_packet_traverse.h) and consecutive single
/// rays revisit the nodes the previous one brought into the cache.
///
/// References
///  [1] S. Woop, C. Benthin, I. Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/triangle.h"

namespace prt {

/// One direction of the fan, prepared for tracing.
struct FanRay {
  glm::vec3 dir{0.0f};    ///< the direction itself
  glm::vec3 inv{0.0f};    ///< SafeInverse(dir), for the slab test
  ShearedRay shear;       ///< axis permutation and shear of the watertight test
  std::uint32_t index = 0;  ///< the direction's index in RayFan::directions
};

/// A direction set prepared for tracing. Build once, trace from any number of origins.
struct RayFan {
  std::vector<glm::vec3> directions;  ///< as given (need not be unit length)
  std::vector<FanRay> rays;           ///< every direction once, in tracing order
};

/// Prepares `directions` and puts them in tracing order (see the file comment). Zero directions
/// are rejected by the caller's contract: every direction must be non-zero and finite.
RayFan MakeRayFan(const std::vector<glm::vec3>& directions);

}  // namespace prt
