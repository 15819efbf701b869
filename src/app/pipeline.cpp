#include "app/pipeline.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "core/log.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "io/obj_loader.h"
#include "io/transport_cache.h"
#include "raster/camera.h"
#include "sh/axis_rotation.h"
#include "env/load_environment.h"
#include "precompute/light.h"
#include "sh/window.h"

namespace prt {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string Format(const char* fmt, double a, double b = 0.0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

}  // namespace

std::unique_ptr<Environment> LoadSceneEnvironment(const SceneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  auto env = LoadEnvironment(options.env, options.layout);
  Summary("environment: " + env->Describe() + Format(" [%.3f s]", SecondsSince(t0)));
  return env;
}

ShRgb ComputeLight(const Environment& env, const SceneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  ShRgb light = ProjectLight(env, options.lmax);
  std::string line = "light: lmax " + std::to_string(options.lmax) + " (" +
                     std::to_string(CoeffCount(options.lmax)) + " coefficients)" +
                     Format(" [%.3f s]", SecondsSince(t0));
  if (options.window == "auto") {
    const AutoWindow choice = ChooseWindow(light);
    ApplyWindow(choice.window, light);
    line += std::string("; window auto -> ") + WindowName(choice.window) +
            Format(" (lowest reconstructed radiance %.3g without, %.3g with)", choice.min_before,
                   choice.min_after);
    if (choice.window == Window::kNone) line += ", no windowing needed: already non-negative";
  } else if (options.window != "none") {
    ApplyWindow(options.window == "hann" ? Window::kHann : Window::kLanczos, light);
    line += "; window " + options.window;
  }
  Summary(line);
  return light;
}

Mesh LoadSceneMesh(const SceneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  Mesh mesh;
  std::string what;
  if (options.mesh.empty()) {
    mesh = MakeDemoScene();
    what = "embedded demo scene (torus knot on a ground plane)";
  } else {
    LoadedMesh loaded = LoadObj(options.mesh);
    for (const auto& w : loaded.report.warnings) Warn(w);
    mesh = std::move(loaded.mesh);
    what = options.mesh;
    if (loaded.report.dropped_degenerate)
      what += ", " + std::to_string(loaded.report.dropped_degenerate) + " zero-area triangles dropped";
    if (loaded.report.recomputed_normals)
      what += ", " + std::to_string(loaded.report.recomputed_normals) + " normals recomputed";
  }
  if (options.albedo) SetUniformAlbedo(mesh, glm::vec3(*options.albedo));
  Summary("mesh: " + what + ": " + std::to_string(mesh.vertex_count()) + " vertices, " +
          std::to_string(mesh.triangle_count()) + " triangles" + Format(" [%.3f s]", SecondsSince(t0)));
  return mesh;
}

TransportOptions TransportOptionsOf(const SceneOptions& options) {
  TransportOptions t;
  t.mode = TransportModeFromName(options.transport);
  t.lmax = options.lmax;
  t.samples = options.samples;
  t.sampler = SamplerFromName(options.sampler);
  t.bounces = options.bounces;
  t.seed = options.seed;
  t.direction_sets = options.direction_sets;
  return t;
}

Transport ComputeSceneTransport(const Mesh& mesh, const SceneOptions& options, const std::string& cache_path) {
  const TransportOptions topts = TransportOptionsOf(options);
  const std::uint64_t key = TransportKey(mesh, topts);
  std::string why;
  if (!cache_path.empty()) {
    if (auto cached = ReadTransportCache(cache_path, key, why)) {
      Summary("transport: taken from the cache " + cache_path + " (same mesh and options)");
      return std::move(*cached);
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  TransportReport r;
  Transport transport = ComputeTransport(mesh, topts, &r);
  const double seconds = SecondsSince(t0);
  std::string line = std::string("transport: ") + TransportModeName(topts.mode) + ", lmax " +
                     std::to_string(topts.lmax) + Format(" [%.3f s]", seconds);
  if (topts.mode == TransportMode::kUnshadowed) {
    line += "; closed form at every vertex: no BVH, no rays";
  } else {
    line += Format("; BVH %.3f s; ", r.bvh_seconds) + std::to_string(r.directions_per_vertex) + " " +
            SamplerName(topts.sampler) + " directions per vertex, " + std::to_string(r.rays) +
            " rays (none below the horizon); " + std::to_string(r.closed_form_vertices) + " of " +
            std::to_string(mesh.vertex_count()) + " vertices unoccluded, given the exact closed form";
  }
  Summary(line);
  if (topts.mode == TransportMode::kInterreflection) {
    std::string bounces = "bounces: ";
    for (std::size_t b = 0; b < r.bounce_share.size(); ++b)
      bounces += Format(b ? ", %.3g" : "%.3g", r.bounce_share[b]);
    if (r.bounce_share.empty()) bounces += "none";
    bounces += " of the direct energy; " + r.bounce_stop + Format(" [%.3f s]", r.bounce_seconds);
    if (transport.channels == 3) bounces += "; coloured albedo: one transport vector per colour channel";
    Summary(bounces);
  }
  if (!cache_path.empty()) {
    if (why != "no cache yet") Summary("cache: " + cache_path + " ignored (" + why + "), recomputed");
    WriteTransportCache(cache_path, transport, key);
  }
  return transport;
}

void RenderJob(const SceneOptions& scene, const RenderOptions& render, const std::string& cache_path) {
  std::error_code ec;
  std::filesystem::create_directories(render.out, ec);
  if (!std::filesystem::is_directory(render.out)) throw Error(render.out + ": cannot create the output folder");
  const auto env = LoadSceneEnvironment(scene);
  const ShRgb light = ComputeLight(*env, scene);
  const Mesh mesh = LoadSceneMesh(scene);
  const Transport transport = ComputeSceneTransport(mesh, scene, cache_path);
  const Camera camera = ChooseCamera(mesh, render);
  Summary("camera: " + CameraArgs(camera));
  const AxisRotation rotation(render.axis, transport.lmax);
  Summary("rotation: " + rotation.Describe() + "; only the " + std::to_string(CoeffCount(transport.lmax)) +
          " coefficients the transport has are turned");

  const FrameStats stats = RenderFrames(mesh, transport, light, *env, camera, render);
  std::string line = "frames: " + std::to_string(stats.frames) + " of " + std::to_string(render.width) + "x" +
                     std::to_string(render.height) + " in " + render.out + "/" +
                     Format(" [draw %.3f s, waiting for PNG encoding %.3f s]", stats.draw_seconds, stats.encode_seconds);
  Summary(line);
  if (stats.negative_pixels > 0)
    Summary("ringing: " + std::to_string(stats.negative_pixels) +
            " pixels over all frames had negative radiance (SH ringing), clamped to 0; --window auto reduces it");
  if (stats.nan_pixels > 0) Summary("warning: " + std::to_string(stats.nan_pixels) + " NaN pixels set to 0");
  if (stats.stale_frames > 0)
    Summary("note: " + std::to_string(stats.stale_frames) + " older frame files numbered from " +
            FrameName(stats.frames) + " on were left untouched (not written by this run)");
}

}  // namespace prt
