#include "geometry/mesh_ops.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace prt {

void Bounds3::Extend(const glm::vec3& p) {
  lo = glm::min(lo, p);
  hi = glm::max(hi, p);
}

float Bounds3::MaxExtent() const {
  const glm::vec3 d = hi - lo;
  return std::max(0.0f, std::max(d.x, std::max(d.y, d.z)));
}

Bounds3 MeshBounds(const Mesh& mesh) {
  Bounds3 b;
  for (const glm::vec3& p : mesh.positions) b.Extend(p);
  return b;
}

void AppendMesh(Mesh& dst, const Mesh& src) {
  if (!dst.triangles.empty() && !src.triangles.empty() && dst.textured() != src.textured())
    throw Error("append mesh: a textured and an untextured mesh (expected both textured or neither)");
  const auto base = static_cast<std::uint32_t>(dst.positions.size());
  dst.positions.insert(dst.positions.end(), src.positions.begin(), src.positions.end());
  dst.normals.insert(dst.normals.end(), src.normals.begin(), src.normals.end());
  dst.albedo.insert(dst.albedo.end(), src.albedo.begin(), src.albedo.end());
  for (const auto& t : src.triangles) dst.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  if (!src.textured()) return;
  const auto texture_base = static_cast<std::uint32_t>(dst.textures.size());
  dst.textures.insert(dst.textures.end(), src.textures.begin(), src.textures.end());
  dst.corner_uv.insert(dst.corner_uv.end(), src.corner_uv.begin(), src.corner_uv.end());
  for (std::uint32_t t : src.triangle_texture) dst.triangle_texture.push_back(t + texture_base);
}

void SetUniformAlbedo(Mesh& mesh, const glm::vec3& albedo) {
  mesh.albedo.assign(mesh.positions.size(), albedo);
  mesh.corner_uv.clear(), mesh.triangle_texture.clear(), mesh.textures.clear();
}

float TriangleDoubleArea(const Mesh& mesh, std::size_t t) {
  const auto& tri = mesh.triangles[t];
  const glm::vec3 a = mesh.positions[tri[0]];
  return glm::length(glm::cross(mesh.positions[tri[1]] - a, mesh.positions[tri[2]] - a));
}

std::vector<glm::vec3> SmoothNormals(const Mesh& mesh) {
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
  for (const auto& tri : mesh.triangles) {
    glm::dvec3 p[3];
    for (int c = 0; c < 3; ++c) p[c] = glm::dvec3(mesh.positions[tri[c]]);
    // Face normal times area: half the cross product.
    const glm::dvec3 area_normal = 0.5 * glm::cross(p[1] - p[0], p[2] - p[0]);
    if (glm::length(area_normal) <= 0.0) continue;
    for (int c = 0; c < 3; ++c) {
      // Corner angle at p[c] between its two edges.
      const glm::dvec3 e1 = p[(c + 1) % 3] - p[c];
      const glm::dvec3 e2 = p[(c + 2) % 3] - p[c];
      const double angle = std::atan2(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2));
      sum[tri[c]] += angle * area_normal;
    }
  }
  std::vector<glm::vec3> normals(sum.size());
  for (std::size_t v = 0; v < sum.size(); ++v) {
    const double len = glm::length(sum[v]);
    normals[v] = len > 0.0 ? glm::vec3(sum[v] / len) : glm::vec3(0.0f, 0.0f, 1.0f);
  }
  return normals;
}

void TransformMesh(Mesh& mesh, float scale, const glm::vec3& offset) {
  for (glm::vec3& p : mesh.positions) p = scale * p + offset;
}

}  // namespace prt
