// Single-ray traversal of Bvh: any hit (Occluded) and closest hit (Intersect), both on the
// 4-wide tree (bvh4_traverse.h).
#include "geometry/bvh.h"
#include "geometry/bvh4_traverse.h"

namespace prt {

bool Bvh::Occluded(const Ray& ray) const {
  if (wide_.nodes.empty()) return false;
  const Ray4 r = MakeRay4(ray.origin, SafeInverse(ray.dir), MakeShearedRay(ray.dir), ray.tmin);
  Hit unused;
  return bvh4::Trace<false>(wide_, r, ray.tmax, unused);
}

std::optional<Hit> Bvh::Intersect(const Ray& ray) const {
  if (wide_.nodes.empty()) return std::nullopt;
  const Ray4 r = MakeRay4(ray.origin, SafeInverse(ray.dir), MakeShearedRay(ray.dir), ray.tmin);
  Hit best;
  if (!bvh4::Trace<true>(wide_, r, ray.tmax, best)) return std::nullopt;
  return best;
}

}  // namespace prt
