#pragma once
/// \file
/// The scene of the transport cache's tests, in the library and through the binary.

#include <glm/vec3.hpp>

#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"

namespace prt::test {

/// A sphere resting on a floor: concave, so samples, seeds and bounces all change its transport.
inline Mesh SphereOnFloor(float radius) {
  Mesh m = MakeSphere(10, radius, glm::vec3(0.0f, radius, 0.0f));
  AppendMesh(m, MakePlane(4.0f, 4));
  SetUniformAlbedo(m, glm::vec3(0.8f));
  return m;
}

}  // namespace prt::test
