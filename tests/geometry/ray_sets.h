#pragma once
// Seeded ray sets shared by the geometry tests: meshes to test on, random rays, rays aimed
// exactly at vertices and along edges, a spherical Fibonacci direction set, and a loop over
// the instruction sets traversal is compiled for.
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/rng.h"
#include "geometry/bvh_kernels.h"
#include "geometry/mesh.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "geometry/ray.h"

namespace prt::test {

struct NamedMesh {
  std::string name;
  Mesh mesh;
};

// `count` triangles with corners uniform in the unit cube (seeded); normals and albedo filled.
inline Mesh RandomSoup(int count, std::uint64_t seed) {
  Pcg32 rng(seed, 7);
  Mesh m;
  auto f = [&] { return static_cast<float>(rng.NextDouble()); };
  for (int i = 0; i < 3 * count; ++i) m.positions.emplace_back(f(), f(), f());
  for (int i = 0; i < count; ++i) {
    const auto b = static_cast<std::uint32_t>(3 * i);
    m.triangles.push_back({b, b + 1, b + 2});
  }
  m.normals = SmoothNormals(m);
  SetUniformAlbedo(m, glm::vec3(0.8f));
  return m;
}

// The differential test meshes: convex, closed with flat faces, concave, and a soup.
inline std::vector<NamedMesh> TestMeshes() {
  return {{"sphere", MakeSphere(24, 1.0f, glm::vec3(0.1f, -0.2f, 0.3f))},
          {"box", MakeBox(glm::vec3(-1.0f, -0.5f, -2.0f), glm::vec3(1.0f, 0.5f, 2.0f), BoxFacing::kOutward, 5)},
          {"torus knot", MakeTorusKnot(2, 3, 0.16f, 48, 8)},
          {"soup", RandomSoup(600, 11)}};
}

inline glm::vec3 UniformSphere(Pcg32& rng) {
  const float z = static_cast<float>(2.0 * rng.NextDouble() - 1.0);
  const float phi = static_cast<float>(2.0 * kPi * rng.NextDouble());
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// `count` rays from origins spread over twice the mesh's box. A quarter go in random
// directions; the others are aimed exactly at a vertex, at a point of an edge, or at a point
// inside a triangle. Some rays get a finite tmax so that hits beyond it must be ignored.
inline std::vector<Ray> DifferentialRays(const Mesh& m, int count, std::uint64_t seed) {
  Pcg32 rng(seed, 3);
  const Bounds3 b = MeshBounds(m);
  const glm::vec3 c = 0.5f * (b.lo + b.hi), half = (b.hi - b.lo);
  auto f = [&] { return static_cast<float>(rng.NextDouble()); };
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    Ray r;
    r.origin = c + half * glm::vec3(2 * f() - 1, 2 * f() - 1, 2 * f() - 1);
    const auto& tri = m.triangles[rng.NextU32() % m.triangle_count()];
    const glm::vec3 p0 = m.positions[tri[0]], p1 = m.positions[tri[1]], p2 = m.positions[tri[2]];
    glm::vec3 target;
    switch (i % 4) {
      case 0: target = r.origin + UniformSphere(rng); break;
      case 1: target = p0; break;
      case 2: target = p0 + f() * (p1 - p0); break;
      default: {
        const float u = f(), v = f() * (1.0f - u);
        target = p0 + u * (p1 - p0) + v * (p2 - p0);
      }
    }
    r.dir = target - r.origin;
    if (glm::length(r.dir) == 0.0f) r.dir = glm::vec3(0, 0, 1);
    if (i % 7 == 0) r.tmax = 0.5f + f();  // t measured in |dir|; about the target's distance
    rays.push_back(r);
  }
  return rays;
}

// Spherical Fibonacci set: z_i = 1 - (2i + 1) / n, phi_i = 2 pi frac(i / golden ratio).
inline std::vector<glm::vec3> FibonacciDirections(int n) {
  std::vector<glm::vec3> d;
  const double golden = (1.0 + std::sqrt(5.0)) / 2.0;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double x = static_cast<double>(i) / golden;
    const double phi = 2.0 * kPi * (x - std::floor(x));
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    d.emplace_back(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
                   static_cast<float>(z));
  }
  return d;
}

// Runs body(name) once with each instruction set this CPU can traverse with (bvh_kernels.h),
// best first, then returns traversal to the best one. Every set must give the same answers.
// (Also when the body throws: later tests must not run on a slower set by accident.)
template <class F>
void ForEachIsa(const F& body) {
  const std::vector<lanes::Isa> isas = SupportedIsas();
  struct Restore {
    lanes::Isa best;
    ~Restore() { UseIsa(best); }
  } restore{isas.front()};
  for (const lanes::Isa isa : isas) {
    UseIsa(isa);
    body(std::string(IsaName(isa)));
  }
}

}  // namespace prt::test
