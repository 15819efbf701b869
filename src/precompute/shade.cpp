#include "precompute/shade.h"

#include <algorithm>

#include "core/error.h"
#include "core/parallel.h"
#include "precompute/transfer_matrix.h"

namespace prt {

std::vector<glm::vec3> ShadeGlossy(const Mesh& mesh, const Transport& transport, const ShRgb& light,
                                   const glm::dvec3* eye) {
  if (!transport.matrices.empty()) {
    if (!eye) throw Error("shading by transfer matrices needs the camera's eye (internal)");
    return GlossyFromMatrices(mesh, transport, transport.material, light, *eye);
  }
  std::vector<glm::vec3> colors(mesh.vertex_count(), glm::vec3(0.0f));
  if (transport.glossy.empty()) return colors;
  const int count = std::min<int>(CoeffCount(transport.lmax), static_cast<int>(light.size()));
  ParallelFor(colors.size(), 1024, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
      for (int c = 0; c < 3; ++c) {
        const float* g = transport.glossy_at(v, c);
        double s = 0.0;
        for (int k = 0; k < count; ++k) s += light[k][c] * g[k];
        colors[v][c] = static_cast<float>(s);
      }
  });
  return colors;
}

void ShadeDiffuseInto(const Mesh& mesh, const Transport& transport, const ShRgb& light, bool albedo,
                      std::vector<glm::vec3>& colors) {
  const int count = std::min<int>(CoeffCount(transport.lmax), static_cast<int>(light.size()));
  colors.resize(mesh.vertex_count());
  ParallelFor(colors.size(), 1024, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      glm::dvec3 sum(0.0);
      for (int c = 0; c < 3; ++c) {
        const float* t = transport.at(v, c);
        double s = 0.0;
        for (int k = 0; k < count; ++k) s += light[k][c] * t[k];
        sum[c] = s;
      }
      colors[v] = albedo ? glm::vec3(glm::dvec3(mesh.albedo[v]) * sum) : glm::vec3(sum);
    }
  });
}

std::vector<glm::vec3> ShadeDiffuse(const Mesh& mesh, const Transport& transport, const ShRgb& light, bool albedo) {
  std::vector<glm::vec3> colors;
  ShadeDiffuseInto(mesh, transport, light, albedo, colors);
  return colors;
}

void ShadeVerticesInto(const Mesh& mesh, const Transport& transport, const ShRgb& light, bool albedo,
                       const glm::dvec3* eye, std::vector<glm::vec3>& colors) {
  ShadeDiffuseInto(mesh, transport, light, albedo, colors);
  if (albedo && transport.material.glossy) {
    const std::vector<glm::vec3> glossy = ShadeGlossy(mesh, transport, light, eye);
    for (std::size_t v = 0; v < colors.size(); ++v) colors[v] += glossy[v];
  }
}

std::vector<glm::vec3> ShadeVertices(const Mesh& mesh, const Transport& transport, const ShRgb& light,
                                     bool albedo, const glm::dvec3* eye) {
  std::vector<glm::vec3> colors;
  ShadeVerticesInto(mesh, transport, light, albedo, eye, colors);
  return colors;
}

}  // namespace prt
