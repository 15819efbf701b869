// Fan traversal of Bvh: each direction of the fan is traced alone through the 8-wide tree
// (bvh_wide_traverse.h) with the inverse and shear the fan computed once for it (ray_fan.h).
// Incoherent rays of one packet visit different nodes; measured on the PRT workload, one ray at
// a time through a 4-wide tree beat packets of 8 through the binary tree by about 5x. Testing
// first the triangles that stopped the previous direction (a shadow cache) was measured too:
// 1024 directions are about 6 degrees apart, so the next ray hits the same block of triangles
// in 0.1 % of cases, and the cache was left out.
#include "core/simd.h"
#include "geometry/bvh.h"
#include "geometry/bvh_wide_traverse.h"
#include "geometry/ray_fan.h"

namespace prt {
namespace {

// Lanes of packet p whose direction is above the horizon of `normal`.
std::uint32_t HorizonLanes(const FanPacket& p, const glm::vec3& normal) {
  std::uint32_t bits = 0;
  for (std::uint32_t l = 0; l < p.count; ++l) {
    const float c = normal.x * p.dir[0][l] + normal.y * p.dir[1][l] + normal.z * p.dir[2][l];
    bits |= (c > 0.0f ? 1u : 0u) << l;
  }
  return bits;
}

// The ray of lane l of packet p from `origin`.
PRT_LANES WideRay LaneRay(const FanPacket& p, int l, const glm::vec3& origin) {
  ShearedRay sr;
  sr.kx = p.kx, sr.ky = p.ky, sr.kz = p.kz;
  sr.sx = p.shear[0][l], sr.sy = p.shear[1][l], sr.sz = p.shear[2][l];
  return MakeWideRay(origin, glm::vec3(p.inv[0][l], p.inv[1][l], p.inv[2][l]), sr, 0.0f);
}

// The fan loops, compiled for AVX2 and for the baseline (core/simd.h).
PRT_VECTORIZED void OccludedLoop(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin,
                                 const glm::vec3& normal, float tmax, std::uint8_t* occluded) {
  Hit unused;
  for (const FanPacket& p : fan.packets) {
    for (std::uint32_t m = HorizonLanes(p, normal); m != 0; m &= m - 1) {
      const int l = __builtin_ctz(m);
      occluded[p.index[l]] = wide::Trace<false>(bvh, LaneRay(p, l, origin), tmax, unused) ? 1 : 0;
    }
  }
}

PRT_VECTORIZED void IntersectLoop(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin,
                                  const glm::vec3& normal, float tmax, std::optional<Hit>* hits) {
  for (const FanPacket& p : fan.packets) {
    for (std::uint32_t m = HorizonLanes(p, normal); m != 0; m &= m - 1) {
      const int l = __builtin_ctz(m);
      Hit h;
      if (wide::Trace<true>(bvh, LaneRay(p, l, origin), tmax, h)) hits[p.index[l]] = h;
    }
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
