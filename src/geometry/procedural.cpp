#include "geometry/procedural.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "geometry/mesh_ops.h"

namespace prt {
namespace {

constexpr float kPiF = static_cast<float>(kPi);

using Index = std::uint32_t;

void AddQuad(Mesh& m, Index a, Index b, Index c, Index d) {  // counter-clockwise a b c d
  m.triangles.push_back({a, b, c});
  m.triangles.push_back({a, c, d});
}

}  // namespace

Mesh MakeSphere(int segments, float radius, const glm::vec3& center, const glm::vec3& albedo) {
  const int seg = std::max(3, segments);
  const int rings = std::max(2, seg / 2);
  Mesh m;
  auto add = [&](const glm::vec3& n) {
    m.positions.push_back(center + radius * n);
    m.normals.push_back(n);
  };
  // Vertex 0 is the north pole, then (rings - 1) latitude circles, then the south pole.
  add(glm::vec3(0.0f, 1.0f, 0.0f));
  for (int r = 1; r < rings; ++r) {
    const float theta = kPiF * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s < seg; ++s) {
      const float phi = 2.0f * kPiF * static_cast<float>(s) / static_cast<float>(seg);
      add(glm::vec3(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)));
    }
  }
  add(glm::vec3(0.0f, -1.0f, 0.0f));
  const auto south = static_cast<Index>(m.positions.size() - 1);
  auto ring = [&](int r, int s) { return static_cast<Index>(1 + (r - 1) * seg + (s % seg)); };
  // Caps: fans around the poles; bands: quads between consecutive circles.
  for (int s = 0; s < seg; ++s) {
    m.triangles.push_back({0, ring(1, s), ring(1, s + 1)});
    m.triangles.push_back({south, ring(rings - 1, s + 1), ring(rings - 1, s)});
    for (int r = 1; r + 1 < rings; ++r) AddQuad(m, ring(r, s), ring(r + 1, s), ring(r + 1, s + 1), ring(r, s + 1));
  }
  SetUniformAlbedo(m, albedo);
  return m;
}

Mesh MakePlane(float size, int divisions, float height, const glm::vec3& albedo) {
  const int n = std::max(1, divisions);
  Mesh m;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const float x = size * (static_cast<float>(j) / static_cast<float>(n) - 0.5f);
      const float z = size * (static_cast<float>(i) / static_cast<float>(n) - 0.5f);
      m.positions.emplace_back(x, height, z);
      m.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  }
  auto at = [&](int i, int j) { return static_cast<Index>(i * (n + 1) + j); };
  // Seen from +Y, +Z then +X is counter-clockwise.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) AddQuad(m, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  SetUniformAlbedo(m, albedo);
  return m;
}

Mesh MakeBox(const glm::vec3& lo, const glm::vec3& hi, BoxFacing facing, int divisions,
             const glm::vec3& albedo) {
  const int n = std::max(1, divisions);
  const float sign = facing == BoxFacing::kOutward ? 1.0f : -1.0f;
  Mesh m;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      // Face on plane coordinate[axis] = lo or hi; (u, v) span it so that u x v = outward.
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const float out = side == 1 ? 1.0f : -1.0f;
      glm::vec3 normal(0.0f);
      normal[axis] = out * sign;
      const auto base = static_cast<Index>(m.positions.size());
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
          glm::vec3 p;
          p[axis] = side == 1 ? hi[axis] : lo[axis];
          p[u] = lo[u] + (hi[u] - lo[u]) * static_cast<float>(i) / static_cast<float>(n);
          p[v] = lo[v] + (hi[v] - lo[v]) * static_cast<float>(j) / static_cast<float>(n);
          m.positions.push_back(p);
          m.normals.push_back(normal);
        }
      }
      auto at = [&](int i, int j) { return static_cast<Index>(base + static_cast<Index>(i * (n + 1) + j)); };
      // (i, j) -> (i+1, j) -> (i+1, j+1) is counter-clockwise about u x v; flip it when the
      // face looks the other way.
      const bool ccw = out * sign > 0.0f;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          if (ccw) AddQuad(m, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
          else AddQuad(m, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
        }
    }
  }
  SetUniformAlbedo(m, albedo);
  return m;
}

Mesh MakeTorusKnot(int p, int q, float tube_radius, int segments, int sides, const glm::vec3& albedo) {
  const int ns = std::max(3, segments), nt = std::max(3, sides);
  const auto fp = static_cast<float>(p), fq = static_cast<float>(q);
  auto curve = [&](float phi) {
    const float r = 2.0f + std::cos(fq * phi);
    return glm::vec3(r * std::cos(fp * phi), r * std::sin(fp * phi), std::sin(fq * phi)) / 3.0f;
  };
  Mesh m;
  for (int i = 0; i < ns; ++i) {
    const float phi = 2.0f * kPiF * static_cast<float>(i) / static_cast<float>(ns);
    const glm::vec3 c = curve(phi);
    // Frame: tangent by central difference, normal = the curve point's direction from the
    // Z axis made orthogonal to the tangent (never parallel to it on a torus knot).
    const float h = 1e-3f;
    const glm::vec3 t = glm::normalize(curve(phi + h) - curve(phi - h));
    const glm::vec3 radial(c.x, c.y, 0.0f);
    const glm::vec3 nrm = glm::normalize(radial - glm::dot(radial, t) * t);
    const glm::vec3 bin = glm::cross(t, nrm);
    for (int j = 0; j < nt; ++j) {
      const float a = 2.0f * kPiF * static_cast<float>(j) / static_cast<float>(nt);
      const glm::vec3 dir = std::cos(a) * nrm + std::sin(a) * bin;
      m.positions.push_back(c + tube_radius * dir);
      m.normals.push_back(dir);
    }
  }
  auto at = [&](int i, int j) { return static_cast<Index>((i % ns) * nt + (j % nt)); };
  // Going around (nrm -> bin) then along t is counter-clockwise seen from outside, because
  // (d dir / da) x t points along dir (outward).
  for (int i = 0; i < ns; ++i)
    for (int j = 0; j < nt; ++j) AddQuad(m, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
  SetUniformAlbedo(m, albedo);
  return m;
}

void StandUpright(Mesh& mesh, float height, float lift) {
  const Bounds3 b = MeshBounds(mesh);
  const float scale = height / (b.hi.y - b.lo.y);
  TransformMesh(mesh, scale, glm::vec3(0.0f, lift - scale * b.lo.y, 0.0f));
}

Mesh MakeKnotOverGround(const KnotOverGround& s) {
  Mesh knot = MakeTorusKnot(2, 3, 0.16f, s.segments, s.sides, s.knot_albedo);
  StandUpright(knot, s.height, s.lift);
  Mesh ground = MakePlane(s.ground_size, s.ground_quads, 0.0f, s.ground_albedo);
  Mesh& first = s.ground_first ? ground : knot;
  AppendMesh(first, s.ground_first ? knot : ground);
  return std::move(first);
}

Mesh MakeDemoScene() {
  // A warm terracotta knot on a light grey ground: colour bleeding shows in the bounces. Per-vertex
  // shading: the ground needs vertices about as dense as its shadows are sharp (96 quads a side).
  return MakeKnotOverGround(KnotOverGround{});
}

}  // namespace prt
