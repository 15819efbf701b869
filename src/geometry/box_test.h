#pragma once
/// \file
/// The slab test of a ray against an axis-aligned box, made conservative as in [1]: the exit
/// distance is enlarged by 2 gamma(3) = 6 eps / (1 - 3 eps) (eps = 2^-24), which bounds the
/// rounding of (bound - origin) * inverse direction, so a box the ray truly touches is never
/// culled. Shared by the single-ray and fan traversals.
///
/// References
///  [1] T. Ize, "Robust BVH Ray Traversal", Journal of Computer Graphics Techniques 2(2), 2013.

#include <cmath>
#include <limits>

#include <glm/vec3.hpp>

namespace prt {

/// 1 + 2 gamma(3) with gamma(n) = n eps / (1 - n eps), eps = 2^-24 [1].
inline constexpr float kSlabFarScale = 1.0f + 2.0f * (3.0f * 0x1.0p-24f) / (1.0f - 3.0f * 0x1.0p-24f);

/// 1 / d, with a zero (or denormal) component replaced by +-FLT_MAX so that
/// (bound - origin) * inverse is never 0 * inf = NaN and a ray parallel to a slab keeps the
/// whole line inside it exactly when its origin is.
inline glm::vec3 SafeInverse(const glm::vec3& d) {
  glm::vec3 inv;
  for (int i = 0; i < 3; ++i)
    inv[i] = std::abs(d[i]) < 1e-30f ? std::copysign(std::numeric_limits<float>::max(), d[i])
                                     : 1.0f / d[i];
  return inv;
}

/// Entry distance of the ray (org, inv) into [lo, hi] clipped to (tmin, tmax), or +inf if the
/// ray misses the box in that interval.
inline float SlabEntry(const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& org,
                       const glm::vec3& inv, float tmin, float tmax) {
  const float tx0 = (lo.x - org.x) * inv.x, tx1 = (hi.x - org.x) * inv.x;
  const float ty0 = (lo.y - org.y) * inv.y, ty1 = (hi.y - org.y) * inv.y;
  const float tz0 = (lo.z - org.z) * inv.z, tz1 = (hi.z - org.z) * inv.z;
  const float tnear = std::max(std::max(std::min(tx0, tx1), std::min(ty0, ty1)),
                               std::max(std::min(tz0, tz1), tmin));
  const float tfar = std::min(std::min(std::max(tx0, tx1), std::max(ty0, ty1)),
                              std::min(std::max(tz0, tz1), tmax)) * kSlabFarScale;
  return tnear <= tfar ? tnear : std::numeric_limits<float>::infinity();
}

}  // namespace prt
