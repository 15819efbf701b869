#include "geometry/brute_force.h"

#include "geometry/triangle.h"

namespace prt {

BruteForceCaster::BruteForceCaster(const Mesh& mesh) {
  corners_.reserve(mesh.triangle_count());
  for (const auto& t : mesh.triangles)
    corners_.push_back({mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]});
}

bool BruteForceCaster::Occluded(const Ray& ray) const {
  const ShearedRay sr = MakeShearedRay(ray.dir);
  float t, u, v;
  for (const auto& c : corners_)
    if (IntersectTriangle(ray.origin, sr, c[0], c[1], c[2], ray.tmin, ray.tmax, t, u, v)) return true;
  return false;
}

std::optional<Hit> BruteForceCaster::Intersect(const Ray& ray) const {
  const ShearedRay sr = MakeShearedRay(ray.dir);
  std::optional<Hit> best;
  float tmax = ray.tmax;
  float t, u, v;
  for (std::size_t i = 0; i < corners_.size(); ++i) {
    const auto& c = corners_[i];
    if (!IntersectTriangle(ray.origin, sr, c[0], c[1], c[2], ray.tmin, tmax, t, u, v)) continue;
    best = Hit{t, static_cast<std::uint32_t>(i), u, v};
    tmax = t;
  }
  return best;
}

}  // namespace prt
