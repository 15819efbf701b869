// The lobe rays of the fixed-camera glossy precompute (precompute/transport_glossy.cpp) traced two
// ways, side by side, on the same scene and threads: as one fan per vertex (Bvh::OccludedFan and
// IntersectFan: the directions prepared, then traced in packets that share their nodes) and one
// ray at a time (Bvh::Occluded and Intersect), for the occlusion rays of shadowed transport and
// the closest-hit rays of interreflection. Both ways answer the same, which is checked. Every
// fourth vertex of the mesh, its lobe's rays drawn as the precompute draws them.
#include <atomic>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench.h"
#include "core/parallel.h"
#include "geometry/bvh.h"
#include "geometry/ray.h"
#include "geometry/ray_fan.h"
#include "material/lobe_transfer.h"
#include "precompute/lobe_rays.h"

namespace prt::bench {

void BenchLobeRays(const Mesh& mesh, const Material& material, const glm::dvec3& eye, int lobe_rays, int runs) {
  const Bvh bvh = Bvh::Build(mesh);
  const float scale = bvh.SceneScale();
  constexpr std::size_t kEvery = 4;
  const std::size_t vertices = (mesh.vertex_count() + kEvery - 1) / kEvery;
  const std::size_t m = static_cast<std::size_t>(lobe_rays);
  // The directions of each traced vertex, drawn once, outside the timing.
  std::vector<glm::vec3> directions(vertices * m);
  ParallelFor(vertices, 64, [&](std::size_t begin, std::size_t end) {
    LobeRays rays;
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t v = i * kEvery;
      const glm::dvec3 r = LobeAxis(glm::dvec3(mesh.normals[v]), glm::dvec3(mesh.positions[v]), eye);
      DrawLobeRays(material.lobe, r, lobe_rays, 1, v, rays);
      for (std::size_t k = 0; k < m; ++k) directions[i * m + k] = glm::vec3(rays.dirs[k]);
    }
  });
  const float inf = std::numeric_limits<float>::infinity();
  // Each way returns what it found (rays blocked, or the sum of the hit triangles' numbers plus
  // one per hit), so that the two can be checked against each other.
  std::atomic<std::uint64_t> found{0};
  const auto fan = [&](bool closest) {
    found = 0;
    ParallelFor(vertices, 32, [&](std::size_t begin, std::size_t end) {
      std::vector<glm::vec3> dirs;
      std::vector<std::uint8_t> blocked;
      std::vector<std::optional<Hit>> hits;
      std::uint64_t count = 0;
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t v = i * kEvery;
        dirs.assign(directions.begin() + std::ptrdiff_t(i * m), directions.begin() + std::ptrdiff_t((i + 1) * m));
        const RayFan rays = MakeRayFan(dirs);
        const glm::vec3 origin = OffsetRayOrigin(mesh.positions[v], mesh.normals[v], scale);
        if (closest) {
          bvh.IntersectFan(rays, origin, mesh.normals[v], inf, hits);
          for (const auto& h : hits) count += h ? 1 + h->triangle : 0;
        } else {
          bvh.OccludedFan(rays, origin, mesh.normals[v], inf, blocked);
          for (std::uint8_t b : blocked) count += b;
        }
      }
      found += count;
    });
    return found.load();
  };
  const auto single = [&](bool closest) {
    found = 0;
    ParallelFor(vertices, 32, [&](std::size_t begin, std::size_t end) {
      std::uint64_t count = 0;
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t v = i * kEvery;
        Ray ray;
        ray.origin = OffsetRayOrigin(mesh.positions[v], mesh.normals[v], scale);
        for (std::size_t k = 0; k < m; ++k) {
          ray.dir = directions[i * m + k];
          if (glm::dot(mesh.normals[v], ray.dir) <= 0.f) continue;  // below the horizon: not traced
          if (closest) {
            const std::optional<Hit> h = bvh.Intersect(ray);
            count += h ? 1 + h->triangle : 0;
          } else {
            count += bvh.Occluded(ray);
          }
        }
      }
      found += count;
    });
    return found.load();
  };
  Print("glossy_lobe_trace_vertices", double(vertices));
  Print("glossy_lobe_trace_rays_per_vertex", double(m));
  for (bool closest : {false, true}) {
    const std::string what = closest ? "closest_hit" : "occlusion";
    std::uint64_t by_fan = 0, by_single = 0;
    const SideBySide t = TimeSideBySide(runs, [&] { by_fan = fan(closest); }, [&] { by_single = single(closest); });
    Print("glossy_lobe_" + what + "_fan_ms", 1e3 * t.ours);
    Print("glossy_lobe_" + what + "_single_ms", 1e3 * t.theirs);
    Print("glossy_lobe_" + what + "_same_answers", by_fan == by_single ? "yes" : "no");
    Print("ratio_lobe_" + what + "_single_vs_fan", t.ratio);  // < 1: single rays are faster
  }
}

}  // namespace prt::bench
