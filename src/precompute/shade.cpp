#include "precompute/shade.h"

#include <algorithm>

#include "core/parallel.h"

namespace prt {

std::vector<glm::vec3> ShadeVertices(const Mesh& mesh, const Transport& transport, const ShRgb& light,
                                     bool albedo) {
  const int count = std::min<int>(CoeffCount(transport.lmax), static_cast<int>(light.size()));
  std::vector<glm::vec3> colors(mesh.vertex_count());
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
      if (transport.glossy.empty() || !albedo) continue;
      for (int c = 0; c < 3; ++c) {
        const float* g = transport.glossy_at(v, c);
        double s = 0.0;
        for (int k = 0; k < count; ++k) s += light[k][c] * g[k];
        colors[v][c] += static_cast<float>(s);
      }
    }
  });
  return colors;
}

}  // namespace prt
