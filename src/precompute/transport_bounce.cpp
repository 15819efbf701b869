// Interreflection: each bounce gathers the previous bounce's transfer from the blocked
// directions, weighted by the albedo at the hit over pi and the cosine at the receiver.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "core/parallel.h"
#include "core/progress.h"
#include "geometry/mesh_texture.h"
#include "precompute/hit_light.h"
#include "precompute/transport_bounce.h"

namespace prt {

double BounceEnergy(const std::vector<double>& t, int count) {
  double sum = 0.0;
  for (std::size_t i = 0; i < t.size(); i += count) sum += t[i];
  return sum;
}

std::vector<double> BounceZero(const std::vector<double>& direct, std::size_t vertices, int channels, int count) {
  const std::size_t stride = static_cast<std::size_t>(channels) * count;
  std::vector<double> current(vertices * stride);
  for (std::size_t v = 0; v < vertices; ++v)
    for (int c = 0; c < channels; ++c)
      std::copy(direct.begin() + v * count, direct.begin() + (v + 1) * count, current.begin() + v * stride + c * count);
  return current;
}

std::uint64_t FrontHits(const std::vector<std::vector<VertexHit>>& hits, const VertexBlock& block) {
  std::uint64_t front = 0;
  for (std::size_t v = std::min(block.begin, hits.size()); v < std::min(block.end, hits.size()); ++v)
    for (const VertexHit& h : hits[v]) front += h.front;
  return front;
}

void BounceRows(const Mesh& mesh, const DirectionPlan& plan, const std::vector<std::vector<VertexHit>>& hits,
                const std::vector<double>& current, int channels, int count, const VertexBlock& block,
                std::vector<double>& next, const std::string& label) {
  const std::size_t nv = mesh.vertex_count();
  const std::size_t stride = static_cast<std::size_t>(channels) * count;
  const bool textured = mesh.textured();
  const std::size_t first = std::min(block.begin, nv), last = std::min(block.end, nv);
  Progress progress(label, last - first);
  ParallelFor(last - first, 64, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = first + begin; v < first + end; ++v) {
      const glm::dvec3 n(mesh.normals[v]);
      const std::size_t directions = plan.PoolOf(v).size();  // the camera's vertices take more
      const double vertex_weight = 4.0 / double(directions);     // (4 pi / N) * (1 / pi)
      double* out = next.data() + v * stride;
      for (const VertexHit& h : hits[v]) {
        if (!h.front) continue;  // the unlit back of a surface reflects nothing
        const double cosine = glm::dot(n, plan.Direction(v, h.dir));
        const glm::vec3 albedo = textured ? HitAlbedo(mesh, v, h.triangle, h.u, h.v, directions) : glm::vec3(0.f);
        for (int c = 0; c < channels; ++c)
          AddHitLight(mesh, h.triangle, h.u, h.v, current, channels, count, c, vertex_weight * cosine, out + c * count,
                      textured ? &albedo : nullptr);
      }
    }
    progress.Advance(end - begin);
  });
}

// Declared in hit_light.h; defined here, where the bounces' loop calls them.
glm::vec3 HitAlbedo(const Mesh& mesh, std::size_t vertex, std::uint32_t triangle, float u, float v,
                    std::size_t directions) {
  const auto& tri = mesh.triangles[triangle];
  const glm::vec3 point = (1.f - u - v) * mesh.positions[tri[0]] + u * mesh.positions[tri[1]] + v * mesh.positions[tri[2]];
  return SurfaceAlbedo(mesh, triangle, u, v, RayFootprint(glm::length(point - mesh.positions[vertex]), directions));
}

void AddHitLight(const Mesh& mesh, std::uint32_t triangle, float u, float v, const std::vector<double>& transfer,
                 int channels, int count, int c, double scale, double* out, const glm::vec3* albedo) {
  const auto& tri = mesh.triangles[triangle];
  const double b[3] = {1.0 - u - v, u, v};
  double rho = 0.0;
  if (albedo)
    rho = (*albedo)[c];
  else
    for (int j = 0; j < 3; ++j) rho += b[j] * mesh.albedo[tri[j]][c];
  const std::size_t stride = std::size_t(channels) * count;
  const double* t0 = transfer.data() + tri[0] * stride + c * count;
  const double* t1 = transfer.data() + tri[1] * stride + c * count;
  const double* t2 = transfer.data() + tri[2] * stride + c * count;
  const double f = scale * rho;
  for (int k = 0; k < count; ++k) out[k] += f * (b[0] * t0[k] + b[1] * t1[k] + b[2] * t2[k]);
}

BounceResult AddBounces(const Mesh& mesh, const DirectionPlan& plan, const DirectResult& direct,
                        const TransportOptions& options, TransportReport& report, bool keep_before_last,
                        std::size_t counted) {
  const int count = CoeffCount(options.lmax);
  const std::size_t nv = mesh.vertex_count();
  BounceResult result;
  result.channels = TransportChannels(mesh, TransportMode::kInterreflection);
  const int channels = result.channels;
  const std::size_t stride = static_cast<std::size_t>(channels) * count;

  // Bounce 0 is the direct transfer, the same for every channel.
  std::vector<double> current = BounceZero(direct.transfer, nv, channels, count);
  result.transfer = current;
  if (keep_before_last) result.before_last = current;
  const double direct_energy = BounceEnergy(current, count);

  VertexBlock own;
  own.end = counted;
  if (FrontHits(direct.hits, own) == 0) {
    report.bounce_stop = "no bounce pass: no vertex sees any lit surface of the mesh";
    return result;
  }
  report.bounce_stop = "all " + std::to_string(options.bounces) + " bounces computed";
  for (int bounce = 1; bounce <= options.bounces; ++bounce) {
    std::vector<double> next(nv * stride, 0.0);
    BounceRows(mesh, plan, direct.hits, current, channels, count, VertexBlock{}, next, "bounce " + std::to_string(bounce));
    if (keep_before_last) result.before_last = result.transfer;
    for (std::size_t i = 0; i < next.size(); ++i) result.transfer[i] += next[i];
    const double share = direct_energy > 0.0 ? BounceEnergy(next, count) / direct_energy : 0.0;
    report.bounce_share.push_back(share);
    if (share < options.bounce_tolerance && bounce < options.bounces) {
      char why[160];
      std::snprintf(why, sizeof why, "stopped after bounce %d of %d: it added %.2g of the direct energy (< %.2g)",
                    bounce, options.bounces, share, options.bounce_tolerance);
      report.bounce_stop = why;
      break;
    }
    current.swap(next);
  }
  return result;
}

}  // namespace prt
