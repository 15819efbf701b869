#include "geometry/ray.h"

#include <algorithm>
#include <cmath>

namespace prt {

glm::vec3 OffsetRayOrigin(const glm::vec3& p, const glm::vec3& n, float scene_scale) {
  const float magnitude =
      std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), std::abs(scene_scale)});
  const float offset = kOffsetUlps * std::numeric_limits<float>::epsilon() * magnitude;
  return p + offset * n;
}

}  // namespace prt
