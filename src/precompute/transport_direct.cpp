// Direct (shadowed) transfer: the closed form minus the Monte Carlo estimate of what is blocked.
#include <atomic>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/parallel.h"
#include "core/progress.h"
#include "geometry/ray.h"
#include "precompute/transport_steps.h"
#include "sh/basis.h"
#include "sh/zonal.h"

namespace prt {

/// Does the ray along `dir` hit the lit side of the triangle, the side its vertex normals face?
/// The side is decided by the triangle's plane (the geometric normal), oriented by the sum of
/// its vertex normals so that the file's winding order does not matter. (Testing the
/// interpolated shading normal instead would call grazing hits on coarse smooth meshes "back"
/// and lose their light.)
bool FrontSide(const Mesh& mesh, const Hit& hit, const glm::vec3& dir) {
  const auto& tri = mesh.triangles[hit.triangle];
  const glm::vec3& p0 = mesh.positions[tri[0]];
  glm::vec3 g = glm::cross(mesh.positions[tri[1]] - p0, mesh.positions[tri[2]] - p0);
  if (glm::dot(g, mesh.normals[tri[0]] + mesh.normals[tri[1]] + mesh.normals[tri[2]]) < 0.0f) g = -g;
  return glm::dot(g, dir) < 0.0f;
}

DirectResult ComputeDirect(const Mesh& mesh, const Bvh& bvh, const DirectionPool& pool, int lmax,
                           bool keep_hits) {
  const int count = CoeffCount(lmax);
  const std::size_t nv = mesh.vertex_count();
  DirectResult result;
  result.transfer.resize(nv * count);
  if (keep_hits) result.hits.resize(nv);
  result.sees_sky.resize(nv);
  const float scene_scale = bvh.SceneScale();
  const double weight = 4.0 / double(pool.size());  // (4 pi / N) * (1 / pi)
  std::atomic<std::uint64_t> rays{0};
  std::atomic<std::size_t> closed{0};
  Progress progress(keep_hits ? "direct transfer (closest hits)" : "shadowed transfer", nv);

  ParallelFor(nv, 64, [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint8_t> blocked;
    std::vector<std::optional<Hit>> hits;
    std::vector<double> y(count), t(count);
    std::uint64_t local_rays = 0;
    std::size_t local_closed = 0;
    for (std::size_t v = begin; v < end; ++v) {
      const std::size_t set = pool.SetOf(v);
      const auto& dirs = pool.sets[set];
      const glm::vec3 n = mesh.normals[v];
      const glm::vec3 origin = OffsetRayOrigin(mesh.positions[v], n, scene_scale);
      if (keep_hits) {
        bvh.IntersectFan(pool.fans[set], origin, n, std::numeric_limits<float>::infinity(), hits);
      } else {
        bvh.OccludedFan(pool.fans[set], origin, n, std::numeric_limits<float>::infinity(), blocked);
      }
      UnshadowedTransfer(lmax, glm::dvec3(n), t.data());
      bool any_blocked = false, any_open = false;
      for (std::size_t i = 0; i < dirs.size(); ++i) {
        const double c = glm::dot(glm::dvec3(n), dirs[i]);
        if (c <= 0.0) continue;
        ++local_rays;
        const bool is_blocked = keep_hits ? hits[i].has_value() : blocked[i] != 0;
        any_open |= !is_blocked;
        if (!is_blocked) continue;
        any_blocked = true;
        EvalBasis(lmax, dirs[i], y.data());
        for (int k = 0; k < count; ++k) t[k] -= weight * c * y[k];
        if (keep_hits) {
          const Hit& h = *hits[i];
          result.hits[v].push_back({h.triangle, h.u, h.v, static_cast<std::uint32_t>(i),
                                    FrontSide(mesh, h, glm::vec3(dirs[i]))});
        }
      }
      if (!any_blocked) ++local_closed;
      result.sees_sky[v] = any_open;
      // Nothing open: the transfer is exactly zero (the estimate of the blocked part would
      // only cancel the closed form up to its sampling noise).
      if (!any_open) std::fill(t.begin(), t.end(), 0.0);
      std::copy(t.begin(), t.end(), result.transfer.begin() + v * count);
    }
    rays += local_rays;
    closed += local_closed;
    progress.Advance(end - begin);
  });
  result.rays = rays;
  result.closed_form_vertices = closed;
  return result;
}

}  // namespace prt
