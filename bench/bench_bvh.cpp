// `prt bench bvh`: the PRT visibility workload on our BVH, brute force and (optionally) Embree 3.
//
// Workload: every vertex of the mesh casts the directions of a 1024-point spherical Fibonacci set
// that lie above its horizon (dot(n, d) > 0), from its position offset off the surface
// (OffsetRayOrigin). Measured with one thread and with all threads; medians of --runs runs.
// Ratios against Embree are medians of per-run ratios, ours and Embree's runs alternating.
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "bench/bench.h"
#include "core/constants.h"
#include "core/parallel.h"
#include "geometry/brute_force.h"
#include "geometry/bvh.h"
#include "geometry/bvh_kernels.h"
#include "geometry/procedural.h"
#include "geometry/ray_fan.h"
#include "io/obj_loader.h"

#ifdef PRT_BENCH_EMBREE
#include "bench/embree_scene.h"
#endif

namespace prt::bench {
namespace {

constexpr int kDirections = 1024;
constexpr std::size_t kGrain = 64;  // vertices per ParallelFor chunk

// Spherical Fibonacci set: z_i = 1 - (2i + 1) / n, phi_i = 2 pi frac(i / golden ratio).
std::vector<glm::vec3> Fibonacci(int n) {
  std::vector<glm::vec3> d;
  const double golden = (1.0 + std::sqrt(5.0)) / 2.0;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n, x = i / golden;
    const double phi = 2.0 * kPi * (x - std::floor(x));
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    d.emplace_back(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
  }
  return d;
}

// The rays of the workload: per vertex an origin and the list of directions above its horizon.
struct Workload {
  std::vector<glm::vec3> origins, normals;
  std::size_t rays = 0;
};

Workload MakeWorkload(const Mesh& mesh, const std::vector<glm::vec3>& dirs, float scene_scale) {
  Workload w;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::vec3 n = mesh.normals[v];
    w.origins.push_back(OffsetRayOrigin(mesh.positions[v], n, scene_scale));
    w.normals.push_back(n);
    for (const glm::vec3& d : dirs) w.rays += n.x * d.x + n.y * d.y + n.z * d.z > 0.0f ? 1 : 0;
  }
  return w;
}

// A run over all vertices: `per_vertex(v)` traces vertex v's rays and returns how many were
// blocked or hit; the run leaves the total in `total`.
template <class F>
std::function<void()> OverVertices(std::size_t vertices, std::size_t& total, const F& per_vertex) {
  return [vertices, &total, per_vertex] {
    std::vector<std::size_t> chunk_counts(ChunkCount(vertices, kGrain));
    ParallelFor(vertices, kGrain, [&](std::size_t b, std::size_t e) {
      std::size_t c = 0;
      for (std::size_t v = b; v < e; ++v) c += per_vertex(v);
      chunk_counts[b / kGrain] = c;
    });
    total = 0;
    for (std::size_t c : chunk_counts) total += c;
  };
}


// Benchmarks one mesh under the name `tag` with `threads` threads.
void BenchMesh(const std::string& tag, const Mesh& mesh, int runs, int threads) {
  Print(tag + "_triangles", static_cast<double>(mesh.triangle_count()));
  Print(tag + "_traversal_isa", IsaName(ActiveKernels().isa));
  Print(tag + "_vertices", static_cast<double>(mesh.vertex_count()));
  SetThreadCount(1);
  Bvh bvh;
  Print(tag + "_build_seconds", MedianSeconds(runs, [&] { bvh = Bvh::Build(mesh); }));
  Print(tag + "_bvh_nodes", static_cast<double>(bvh.nodes().size()));
  const std::vector<glm::vec3> dirs = Fibonacci(kDirections);
  const RayFan fan = MakeRayFan(dirs);
  const Workload w = MakeWorkload(mesh, dirs, bvh.SceneScale());
  Print(tag + "_wide_nodes", static_cast<double>(bvh.wide().nodes.size()));
  Print(tag + "_rays", static_cast<double>(w.rays));
  const double mrays = static_cast<double>(w.rays) * 1e-6;
  const float inf = std::numeric_limits<float>::infinity();
#ifdef PRT_BENCH_EMBREE
  EmbreeScene embree(mesh);
#endif
  const std::vector<int> thread_counts = threads == 1 ? std::vector<int>{1} : std::vector<int>{1, threads};
  for (const int t : thread_counts) {  // one thread only once when all threads is one
    SetThreadCount(t);
    const std::string key = tag + "_t" + std::to_string(ThreadCount());
    std::size_t occluded = 0, hits = 0, single = 0;
    const auto ours_occluded = OverVertices(mesh.vertex_count(), occluded, [&](std::size_t v) {
      thread_local std::vector<std::uint8_t> mask;
      bvh.OccludedFan(fan, w.origins[v], w.normals[v], inf, mask);
      std::size_t c = 0;
      for (auto m : mask) c += m;
      return c;
    });
    const auto ours_intersect = OverVertices(mesh.vertex_count(), hits, [&](std::size_t v) {
      thread_local std::vector<std::optional<Hit>> out;
      bvh.IntersectFan(fan, w.origins[v], w.normals[v], inf, out);
      std::size_t c = 0;
      for (const auto& h : out) c += h ? 1 : 0;
      return c;
    });
    const auto ours_single = OverVertices(mesh.vertex_count(), single, [&](std::size_t v) {
      std::size_t c = 0;
      for (const glm::vec3& d : dirs)
        if (glm::dot(w.normals[v], d) > 0.0f) c += bvh.Occluded(Ray{w.origins[v], d}) ? 1 : 0;
      return c;
    });
#ifdef PRT_BENCH_EMBREE
    // Embree traces exactly the same rays, alternating with ours run by run (TimeSideBySide).
    std::size_t e_occ = 0, e_hits = 0;
    const auto embree_occluded = OverVertices(mesh.vertex_count(), e_occ, [&](std::size_t v) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      std::size_t c = 0;
      for (const glm::vec3& d : dirs) {
        if (!(w.normals[v].x * d.x + w.normals[v].y * d.y + w.normals[v].z * d.z > 0.0f)) continue;
        RTCRay r = embree.MakeRay(w.origins[v], d);
        rtcOccluded1(embree.scene, &ctx, &r);
        c += r.tfar < 0.0f ? 1 : 0;
      }
      return c;
    });
    const auto embree_intersect = OverVertices(mesh.vertex_count(), e_hits, [&](std::size_t v) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      std::size_t c = 0;
      for (const glm::vec3& d : dirs) {
        if (!(w.normals[v].x * d.x + w.normals[v].y * d.y + w.normals[v].z * d.z > 0.0f)) continue;
        RTCRayHit rh{};
        rh.ray = embree.MakeRay(w.origins[v], d);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(embree.scene, &ctx, &rh);
        c += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? 1 : 0;
      }
      return c;
    });
    const SideBySide occ = TimeSideBySide(runs, ours_occluded, embree_occluded);
    const SideBySide isect = TimeSideBySide(runs, ours_intersect, embree_intersect);
#else
    const SideBySide occ{MedianSeconds(runs, ours_occluded), 0.0, 0.0};
    const SideBySide isect{MedianSeconds(runs, ours_intersect), 0.0, 0.0};
#endif
    const double one = MedianSeconds(runs, ours_single);
    Print(key + "_occluded_fraction", static_cast<double>(occluded) / static_cast<double>(w.rays));
    Print(key + "_fan_occluded_mrays_per_s", mrays / occ.ours);
    Print(key + "_fan_intersect_mrays_per_s", mrays / isect.ours);
    Print(key + "_single_ray_occluded_mrays_per_s", mrays / one);
    Print(key + "_fan_agrees_with_single_ray", occluded == single && occluded == hits ? "yes" : "no");
#ifdef PRT_BENCH_EMBREE
    Print(key + "_embree_occluded_mrays_per_s", mrays / occ.theirs);
    Print(key + "_embree_intersect_mrays_per_s", mrays / isect.theirs);
    Print(key + "_embree_occluded_fraction", static_cast<double>(e_occ) / static_cast<double>(w.rays));
    Print(key + "_ratio_occluded_vs_embree", occ.ratio);
    Print(key + "_ratio_intersect_vs_embree", isect.ratio);
    if (t == 1 && tag == "knot") {  // the headline numbers: procedural mesh, one thread
      Print("ratio_occluded_vs_embree", occ.ratio);
      Print("ratio_intersect_vs_embree", isect.ratio);
    }
#endif
  }
}

// Brute force on a small mesh, for scale: the reference the BVH is tested against.
void BenchBruteForce(int runs) {
  const Mesh small = MakeSphere(24);  // 528 triangles
  const BruteForceCaster bf(small);
  const std::vector<glm::vec3> dirs = Fibonacci(kDirections);
  const Workload w = MakeWorkload(small, dirs, 2.0f);
  SetThreadCount(1);
  std::size_t count = 0;
  const double s = MedianSeconds(runs, OverVertices(small.vertex_count(), count, [&](std::size_t v) {
    std::size_t c = 0;
    for (const glm::vec3& d : dirs)
      if (glm::dot(w.normals[v], d) > 0.0f) c += bf.Intersect(Ray{w.origins[v], d}) ? 1 : 0;
    return c;
  }));
  Print("brute_force_triangles", static_cast<double>(small.triangle_count()));
  Print("brute_force_t1_intersect_mrays_per_s", static_cast<double>(w.rays) * 1e-6 / s);
}

}  // namespace

int BenchBvh(Args& args) {
  const auto mesh_path = args.String("--mesh");
  const int runs = args.Int("--runs", 3, 1, 1000);
  const int threads = args.Int("--threads", 0, 0, 1024);
  args.Finish();
  const int all = threads > 0 ? threads : ThreadCount();
  Print("directions", static_cast<double>(kDirections));
  Print("runs", static_cast<double>(runs));
  // A concave procedural mesh of 102,400 triangles: a torus knot, whose lobes shadow each other.
  BenchMesh("knot", MakeTorusKnot(2, 3, 0.16f, 1024, 50), runs, all);
  if (mesh_path) BenchMesh("mesh", LoadObj(*mesh_path).mesh, runs, all);
  BenchBruteForce(runs);
  SetThreadCount(threads);
  return 0;
}

}  // namespace prt::bench
