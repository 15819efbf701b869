#pragma once
/// \file
/// The reference ray caster: every ray against every triangle. Slow (O(triangles) per ray) and
/// obviously right; the BVH is tested against it (as nori's first accelerator is replaced by a
/// BVH behind the same interface).

#include <array>
#include <optional>
#include <vector>

#include "geometry/mesh.h"
#include "geometry/ray.h"

namespace prt {

class BruteForceCaster {
 public:
  /// Copies the triangles' corner positions out of `mesh`.
  explicit BruteForceCaster(const Mesh& mesh);

  /// True if the ray hits any triangle with t in (ray.tmin, ray.tmax).
  bool Occluded(const Ray& ray) const;

  /// The hit with the smallest t in (ray.tmin, ray.tmax); of hits at the same t (a ray through
  /// a shared edge) the first found, in triangle order, is kept.
  std::optional<Hit> Intersect(const Ray& ray) const;

 private:
  std::vector<std::array<glm::vec3, 3>> corners_;
};

}  // namespace prt
