// Fan traversal of Bvh: each direction of the fan is traced alone through the 8-wide tree
// (bvh_wide_traverse.h) with the inverse and shear the fan computed once for it (ray_fan.h).
// Neighbouring directions from one vertex diverge quickly and visit different nodes; measured
// on the PRT workload, one ray at a time through a 4-wide tree beat packets of 8 directions
// through the binary tree by about 5x. Testing first the triangles that stopped the previous
// direction (a shadow cache) was measured too: 1024 directions are about 6 degrees apart, so
// the next ray hits the same block of triangles in 0.1 % of cases, and the cache was left out.
#include <glm/geometric.hpp>

#include "core/simd.h"
#include "geometry/bvh.h"
#include "geometry/bvh_wide_traverse.h"
#include "geometry/ray_fan.h"

namespace prt {
namespace {

// The fan loops, compiled for AVX2 and for the baseline (core/simd.h). Directions at or below
// the horizon of `normal` cast no ray.
PRT_VECTORIZED void OccludedLoop(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin,
                                 const glm::vec3& normal, float tmax, std::uint8_t* occluded) {
  Hit unused;
  for (const FanRay& f : fan.rays) {
    if (!(glm::dot(normal, f.dir) > 0.0f)) continue;
    occluded[f.index] = wide::Trace<false>(bvh, MakeWideRay(origin, f.inv, f.shear, 0.0f), tmax, unused) ? 1 : 0;
  }
}

PRT_VECTORIZED void IntersectLoop(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin,
                                  const glm::vec3& normal, float tmax, std::optional<Hit>* hits) {
  for (const FanRay& f : fan.rays) {
    if (!(glm::dot(normal, f.dir) > 0.0f)) continue;
    Hit h;
    if (wide::Trace<true>(bvh, MakeWideRay(origin, f.inv, f.shear, 0.0f), tmax, h)) hits[f.index] = h;
  }
}

}  // namespace

void Bvh::OccludedFan(const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal, float tmax,
                      std::vector<std::uint8_t>& occluded) const {
  occluded.assign(fan.directions.size(), 0);
  if (wide_.nodes.empty()) return;
  OccludedLoop(wide_, fan, origin, normal, tmax, occluded.data());
}

void Bvh::IntersectFan(const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal, float tmax,
                       std::vector<std::optional<Hit>>& hits) const {
  hits.assign(fan.directions.size(), std::nullopt);
  if (wide_.nodes.empty()) return;
  IntersectLoop(wide_, fan, origin, normal, tmax, hits.data());
}

}  // namespace prt
