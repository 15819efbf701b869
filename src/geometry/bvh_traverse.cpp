// Single-ray traversal of Bvh: any hit (Occluded) and closest hit (Intersect), both on the
// 8-wide tree (bvh_wide_traverse.h), compiled for AVX2 and for the baseline (core/simd.h).
#include "core/simd.h"
#include "geometry/bvh.h"
#include "geometry/bvh_wide_traverse.h"

namespace prt {
namespace {

PRT_VECTORIZED bool TraceOne(const WideBvh& bvh, const Ray& ray, bool closest, Hit& best) {
  const WideRay r = MakeWideRay(ray.origin, SafeInverse(ray.dir), MakeShearedRay(ray.dir), ray.tmin);
  return closest ? wide::Trace<true>(bvh, r, ray.tmax, best) : wide::Trace<false>(bvh, r, ray.tmax, best);
}

}  // namespace

bool Bvh::Occluded(const Ray& ray) const {
  if (wide_.nodes.empty()) return false;
  Hit unused;
  return TraceOne(wide_, ray, false, unused);
}

std::optional<Hit> Bvh::Intersect(const Ray& ray) const {
  if (wide_.nodes.empty()) return std::nullopt;
  Hit best;
  if (!TraceOne(wide_, ray, true, best)) return std::nullopt;
  return best;
}

}  // namespace prt
