#pragma once
/// \file
/// An orthonormal frame about a unit vector, without branches or a helper axis: Duff, Burgess,
/// Christensen, Hery, Kensler, Liani, Villemin, "Building an Orthonormal Basis, Revisited",
/// JCGT 6(1), 2017. (t, b, n) is right-handed.

#include <cmath>

#include <glm/vec3.hpp>

namespace prt {

/// Unit vectors t and b completing the unit vector n to a right-handed frame (t, b, n).
inline void TangentFrame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z), c = n.x * n.y * a;
  t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

}  // namespace prt
