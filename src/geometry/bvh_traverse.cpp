// Traversal entry points of Bvh: single rays and fans, run by the kernels of the instruction
// set chosen for this CPU (bvh_kernels.h) on the 8-wide tree.
#include "geometry/bvh.h"
#include "geometry/bvh_kernels.h"
#include "geometry/ray_fan.h"

namespace prt {

bool Bvh::Occluded(const Ray& ray) const {
  if (wide_.nodes.empty()) return false;
  Hit unused;
  return ActiveKernels().trace(wide_, ray, false, unused);
}

std::optional<Hit> Bvh::Intersect(const Ray& ray) const {
  if (wide_.nodes.empty()) return std::nullopt;
  Hit best;
  if (!ActiveKernels().trace(wide_, ray, true, best)) return std::nullopt;
  return best;
}

void Bvh::OccludedFan(const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal, float tmax,
                      std::vector<std::uint8_t>& occluded) const {
  occluded.assign(fan.directions.size(), 0);
  if (wide_.nodes.empty()) return;
  ActiveKernels().occluded_fan(wide_, fan, origin, normal, tmax, occluded.data());
}

void Bvh::IntersectFan(const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal, float tmax,
                       std::vector<std::optional<Hit>>& hits) const {
  hits.assign(fan.directions.size(), std::nullopt);
  if (wide_.nodes.empty()) return;
  ActiveKernels().intersect_fan(wide_, fan, origin, normal, tmax, hits.data());
}

}  // namespace prt
