// prt_embree_precompute: the baseline of bench/precompute_vs_embree.sh. A straightforward
// Embree-based precompute of the same work as
//
//   prt precompute --mesh M --env E --samples N --out DIR      (shadowed transport, lmax 2)
//
// It reuses prt's own code for everything except visibility, so that the comparison measures
// the ray tracing and what prt does around it, not two different loaders or writers: the scene
// loading (OBJ, welding, orientation; LoadSceneMesh), the environment and its light projection
// (LoadSceneEnvironment, ComputeLight), the same direction pool (MakeDirectionPool: the same
// sets, the same set per vertex), the same offset ray origins (OffsetRayOrigin with the scene's
// largest bounding-box side), the same estimator and the same writers of light.txt and
// transport.txt (FormatLightTxt, FormatTransportTxt, WriteFileAtomic).
//
// Visibility: one Embree 3 scene (rtcNewDevice, one triangle geometry, rtcCommitScene with the
// default flags and build quality) and one rtcOccluded1 per ray above the horizon, in a plain
// loop over the vertices (ParallelFor over vertices, grain 64, all threads), directions in the
// set's own order.
//
// The estimator is prt's (precompute/transport_direct.cpp): per vertex, the unshadowed closed
// form (A_l/pi) Y(n) minus (4 pi / N)(1/pi) sum over blocked directions w_i with n.w_i > 0 of
// (n.w_i) Y(w_i); zero when every direction above the horizon is blocked. prt counts the
// vertices it finds unoccluded (they keep the closed form exactly) for its run summary; the
// baseline does not count them (it gets the same closed form for them by the same
// subtraction of nothing).
//
// No cache, no output-folder bookkeeping (lock, record of inputs), no progress bar; the run
// summary lines of the shared stages are printed as prt prints them (--quiet silences them).
//
// Usage: prt_embree_precompute [--mesh M] [--env E] [--samples N] [--threads T] [--quiet] --out DIR
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/pipeline.h"
#include "app/scene_options.h"
#include "bench/embree_scene.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/parallel.h"
#include "core/text.h"
#include "geometry/ray.h"
#include "precompute/direction_pool.h"
#include "precompute/samplers.h"
#include "precompute_io/light_txt.h"
#include "precompute_io/transport_txt.h"
#include "sh/basis.h"
#include "sh/zonal.h"

namespace {

using namespace prt;
using prt::bench::EmbreeScene;

[[noreturn]] void Usage(const char* why) {
  std::fprintf(stderr,
               "prt_embree_precompute: %s\nusage: prt_embree_precompute [--mesh M] [--env E] [--samples N] "
               "[--threads T] [--quiet] --out DIR\n",
               why);
  std::exit(2);
}


/// Largest side of the triangles' bounding box: prt's Bvh::SceneScale (its root box).
float SceneScale(const Mesh& mesh) {
  if (mesh.triangles.empty()) return 0.0f;
  glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  for (const auto& tri : mesh.triangles)
    for (std::uint32_t i : tri) {
      lo = glm::min(lo, mesh.positions[i]);
      hi = glm::max(hi, mesh.positions[i]);
    }
  const glm::vec3 d = hi - lo;
  return std::max(d.x, std::max(d.y, d.z));
}

/// Shadowed transfer of every vertex, visibility by Embree: prt's estimator (see the file comment).
Transport EmbreeShadowedTransport(const Mesh& mesh, const DirectionPool& pool, int lmax, std::uint64_t& rays_out) {
  const EmbreeScene embree(mesh);
  const int count = CoeffCount(lmax);
  const std::size_t nv = mesh.vertex_count();
  std::vector<double> transfer(nv * count);
  const float scene_scale = SceneScale(mesh);
  const double weight = 4.0 / double(pool.size());  // (4 pi / N) * (1 / pi)
  std::atomic<std::uint64_t> rays{0};
  ParallelFor(nv, 64, [&](std::size_t begin, std::size_t end) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    std::vector<double> y(count), t(count);
    std::uint64_t local_rays = 0;
    for (std::size_t v = begin; v < end; ++v) {
      const auto& dirs = pool.sets[pool.SetOf(v)];
      const glm::vec3 n = mesh.normals[v];
      const glm::vec3 origin = OffsetRayOrigin(mesh.positions[v], n, scene_scale);
      UnshadowedTransfer(lmax, glm::dvec3(n), t.data());
      bool any_open = false;
      for (std::size_t i = 0; i < dirs.size(); ++i) {
        const double c = glm::dot(glm::dvec3(n), dirs[i]);
        if (c <= 0.0) continue;
        ++local_rays;
        const glm::vec3 d(dirs[i]);
        RTCRay r{};
        r.org_x = origin.x, r.org_y = origin.y, r.org_z = origin.z;
        r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z;
        r.tnear = 0.0f, r.tfar = std::numeric_limits<float>::infinity(), r.mask = 0xFFFFFFFFu;
        rtcOccluded1(embree.scene, &ctx, &r);
        if (!(r.tfar < 0.0f)) {
          any_open = true;
          continue;
        }
        EvalBasis(lmax, dirs[i], y.data());
        for (int k = 0; k < count; ++k) t[k] -= weight * c * y[k];
      }
      if (!any_open) std::fill(t.begin(), t.end(), 0.0);  // nothing open: exactly zero, as prt
      std::copy(t.begin(), t.end(), transfer.begin() + v * count);
    }
    rays += local_rays;
  });
  rays_out = rays;
  Transport transport;
  transport.lmax = lmax;
  transport.vertices = nv;
  transport.coeffs.assign(transfer.begin(), transfer.end());
  return transport;
}

}  // namespace

int main(int argc, char** argv) {
  SceneOptions options;  // lmax 2, shadowed, fibonacci, 64 direction sets, seed 1: prt's defaults
  options.env = "sky";
  options.samples = 1024;
  std::string out;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) Usage((a + " needs a value").c_str());
      return argv[++i];
    };
    if (a == "--mesh") options.mesh = value();
    else if (a == "--env") options.env = value();
    else if (a == "--samples") options.samples = std::atoi(value().c_str());
    else if (a == "--threads") options.threads = std::atoi(value().c_str());
    else if (a == "--out") out = value();
    else if (a == "--quiet") SetQuiet(true);
    else Usage(("unknown option " + a).c_str());
  }
  if (out.empty()) Usage("--out DIR is required");
  if (options.samples <= 0) Usage("--samples must be positive");
  try {
    SetThreadCount(options.threads);
    std::filesystem::create_directories(out);
    const Mesh mesh = LoadSceneMesh(options);
    const auto env = LoadSceneEnvironment(options);
    const ShRgb light = ComputeLight(*env, options);

    const auto t0 = std::chrono::steady_clock::now();
    const DirectionPool pool = MakeDirectionPool(SamplerFromName(options.sampler), options.samples,
                                                 options.direction_sets, options.seed);
    std::uint64_t rays = 0;
    const Transport transport = EmbreeShadowedTransport(mesh, pool, options.lmax, rays);
    Summary("transport: shadowed (Embree 3, rtcOccluded1), lmax " + std::to_string(options.lmax) + ", " +
            std::to_string(pool.size()) + " directions per vertex, " + std::to_string(rays) + " rays" +
            Formatted(" [%.3f s]", SecondsSince(t0)));

    WriteFileAtomic(out + "/light.txt", FormatLightTxt(light));
    WriteFileAtomic(out + "/transport.txt", FormatTransportTxt(mesh, transport, 0));
    Summary("wrote " + out + "/light.txt and " + out + "/transport.txt");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "prt_embree_precompute: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
