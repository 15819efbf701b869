#include "precompute/bounce_senders.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "geometry/mesh_ops.h"
#include "geometry/subdivide.h"

namespace prt {

std::optional<Mesh> RefineSenders(const Mesh& mesh, SenderRefinement& report) {
  report = SenderRefinement{};
  const Bounds3 box = MeshBounds(mesh);
  const float max_edge = static_cast<float>(kSenderEdge * glm::length(glm::dvec3(box.hi - box.lo)));
  report.max_edge = max_edge;
  if (!(max_edge > MinimumMaxEdge(mesh))) return std::nullopt;  // a degenerate box: nothing to split
  const float limit2 = max_edge * max_edge;
  for (const auto& t : mesh.triangles) {
    for (int c = 0; c < 3 && !report.needed; ++c) {
      const glm::vec3 d = mesh.positions[t[c]] - mesh.positions[t[(c + 1) % 3]];
      report.needed = glm::dot(d, d) > limit2;
    }
    if (report.needed) break;
  }
  if (!report.needed) return std::nullopt;
  const std::size_t allowed = std::max(kSenderTriangleFactor * mesh.triangle_count(), kSenderMinTriangles);
  report.triangles_estimate = EstimateSplitTriangles(mesh, max_edge);
  if (report.triangles_estimate > allowed) return std::nullopt;
  Mesh refined = mesh;
  report.vertices_added = SplitLongEdges(refined, max_edge).vertices_added;
  report.done = true;
  return refined;
}

}  // namespace prt
