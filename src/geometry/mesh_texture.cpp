#include "geometry/mesh_texture.h"

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "texture/texture.h"

namespace prt {

glm::vec2 TriangleUv(const Mesh& mesh, std::uint32_t t, float u, float v) {
  const glm::vec2* c = &mesh.corner_uv[3 * std::size_t(t)];
  return (1.f - u - v) * c[0] + u * c[1] + v * c[2];
}

float UvPerWorldUnit(const Mesh& mesh, std::uint32_t t) {
  const auto& tri = mesh.triangles[t];
  const glm::vec3 e1 = mesh.positions[tri[1]] - mesh.positions[tri[0]];
  const glm::vec3 e2 = mesh.positions[tri[2]] - mesh.positions[tri[0]];
  const glm::vec2* c = &mesh.corner_uv[3 * std::size_t(t)];
  const glm::vec2 f1 = c[1] - c[0], f2 = c[2] - c[0];
  const float world = glm::length(glm::cross(e1, e2)), uv = std::fabs(f1.x * f2.y - f1.y * f2.x);
  return world > 0.f ? std::sqrt(uv / world) : 0.f;
}

glm::vec3 SurfaceAlbedo(const Mesh& mesh, std::uint32_t t, float u, float v, float footprint) {
  if (!mesh.textured()) {
    const auto& tri = mesh.triangles[t];
    return (1.f - u - v) * mesh.albedo[tri[0]] + u * mesh.albedo[tri[1]] + v * mesh.albedo[tri[2]];
  }
  const Texture& texture = *mesh.textures[mesh.triangle_texture[t]];
  const float extent = footprint * UvPerWorldUnit(mesh, t);
  return texture.Sample(TriangleUv(mesh, t, u, v), texture.LodOf({extent, 0.f}, {0.f, extent}));
}

float RayFootprint(float distance, std::size_t directions) {
  constexpr float kFourPi = 12.566370614359172f;
  return distance * std::sqrt(kFourPi / static_cast<float>(directions));
}

void SetVertexAlbedoFromTextures(Mesh& mesh) {
  if (!mesh.textured()) return;
  std::vector<glm::vec3> sum(mesh.vertex_count(), glm::vec3(0.f));
  std::vector<float> corners(mesh.vertex_count(), 0.f);
  for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
    const Texture& texture = *mesh.textures[mesh.triangle_texture[t]];
    // The triangle's width: the side of a square of its area, in texture coordinates.
    const glm::vec2* c = &mesh.corner_uv[3 * std::size_t(t)];
    const glm::vec2 f1 = c[1] - c[0], f2 = c[2] - c[0];
    const float extent = std::sqrt(0.5f * std::fabs(f1.x * f2.y - f1.y * f2.x));
    const float lod = texture.LodOf({extent, 0.f}, {0.f, extent});
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t vertex = mesh.triangles[t][k];
      sum[vertex] += texture.Sample(c[k], lod);
      corners[vertex] += 1.f;
    }
  }
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    if (corners[v] > 0.f) mesh.albedo[v] = sum[v] / corners[v];
}

}  // namespace prt
