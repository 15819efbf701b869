#pragma once
// Scenes and lights shared by the glossy transfer tests.
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "material/material.h"
#include "precompute/transport.h"
#include "sh/basis.h"
#include "sh/coeffs.h"

namespace prt::test {

/// A sphere hovering over a plane (y = 0, centred on the Y axis): the plane's vertices under it
/// are occluded, the sphere's underside sees the plane.
struct SphereOverPlaneShape {
  float plane_size = 6.0f;
  int plane_divisions = 12;
  int sphere_segments = 16;
  float radius = 1.0f;
  float height = 1.2f;  ///< of the sphere's centre
  glm::vec3 albedo{0.5f};
};

inline Mesh SphereOverPlane(const SphereOverPlaneShape& s = {}) {
  Mesh mesh = MakePlane(s.plane_size, s.plane_divisions, 0.0f, s.albedo);
  AppendMesh(mesh, MakeSphere(s.sphere_segments, s.radius, glm::vec3(0.0f, s.height, 0.0f), s.albedo));
  return mesh;
}

/// SphereOverPlane with its glossy transfer matrices at lmax 2 from 64 directions, for the
/// material `phong`: shadowed, or with one vertex coloured and interreflection, whose matrices
/// then differ per channel (three).
struct GlossyMatrixScene {
  Mesh mesh;
  Transport transport;
};

inline GlossyMatrixScene MakeGlossyMatrixScene(bool coloured, const char* phong) {
  GlossyMatrixScene s;
  s.mesh = SphereOverPlane();
  if (coloured) s.mesh.albedo[3] = glm::vec3(0.2f, 0.4f, 0.3f);
  TransportOptions o;
  o.mode = coloured ? TransportMode::kInterreflection : TransportMode::kShadowed;
  o.lmax = 2;
  o.samples = 64;
  o.material = ParseMaterial(phong);
  o.matrices = true;
  s.transport = ComputeTransport(s.mesh, o, nullptr);
  return s;
}

/// A light positive everywhere with every coefficient of bands 0..lmax in use, different per
/// channel.
inline ShRgb BandLimitedLight(int lmax) {
  ShRgb light(CoeffCount(lmax));
  for (std::size_t k = 0; k < light.size(); ++k) {
    const double x = double(k);
    light[k] = glm::dvec3(0.05 * std::sin(1.3 * x + 0.2), 0.04 * std::cos(0.7 * x), 0.03 * std::sin(2.1 * x + 1.0));
  }
  light[0] = glm::dvec3(2.0, 1.5, 1.0);
  return light;
}

/// The light's radiance from direction d, sum_k L_k Y_k(d).
inline glm::dvec3 LightAt(const ShRgb& light, const glm::dvec3& d) {
  std::vector<double> y(light.size());
  EvalBasis(LmaxOfCount(light.size()), d, y.data());
  glm::dvec3 sum(0.0);
  for (std::size_t k = 0; k < light.size(); ++k) sum += y[k] * light[k];
  return sum;
}

}  // namespace prt::test
