// prt reference: the ground truth without SH truncation (precompute/reference.h), as per-vertex
// text and as a picture drawn like frame 0 of `render`.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/commands.h"
#include "app/pipeline.h"
#include "app/report_image.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "io/png_io.h"
#include "precompute/reference.h"

namespace prt {

const char* const kReferenceHelp =
    "usage: prt reference [scene options] [render options] --out DIR\n"
    "  Ground truth without SH truncation: each vertex's outgoing radiance, the environment\n"
    "  integrated directly against max(0, n.w) V(w) albedo/pi by importance-sampled, randomly\n"
    "  shifted lattice directions (plus per-vertex path tracing of --bounces bounces for\n"
    "  --transport interreflection). Its own error is estimated from two independent halves.\n"
    "  Writes DIR/reference.txt (vertex count, then one `R G B` line per vertex) and\n"
    "  DIR/reference.png (the mesh drawn with these colours by the rasterizer, camera and tone\n"
    "  mapping of `render`'s frame 0; --size, --eye, --tonemap ... apply, frame options do not).\n"
    "  --out DIR                 output folder, created if missing (required)\n"
    "  --reference-samples N     directions per vertex, 2..16777216 (default 8192)\n";

int RunReference(const std::vector<std::string>& tokens) {
  Args args("reference", tokens, SceneFlags());
  const SceneOptions scene = ReadSceneOptions(args);
  const int samples = args.Int("--reference-samples", 8192, 2, 1 << 24);
  RenderOptions defaults = ReportRenderOptions(640, 480);
  defaults.out = "";
  const RenderOptions render = ReadRenderOptions(args, defaults);
  args.Finish();
  if (render.out.empty()) throw UsageError("--out DIR is required", "reference");
  std::error_code ec;
  std::filesystem::create_directories(render.out, ec);
  if (!std::filesystem::is_directory(render.out)) throw Error(render.out + ": cannot create the output folder");

  const auto env = LoadSceneEnvironment(scene);
  const Mesh mesh = LoadSceneMesh(scene);
  ReferenceOptions ro;
  ro.mode = TransportModeFromName(scene.transport);
  ro.samples = samples;
  ro.bounces = scene.bounces;
  ro.seed = scene.seed;
  const auto t0 = std::chrono::steady_clock::now();
  const Reference ref = ComputeReference(mesh, *env, ro);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  char line[400];
  std::snprintf(line, sizeof line,
                "reference: %s, %d importance-sampled lattice directions per vertex in two halves, %llu rays "
                "[%.3f s]; estimated RMS error %.3g (%.3g%% of the RMS radiance %.3g)",
                TransportModeName(ro.mode), 2 * (samples / 2), static_cast<unsigned long long>(ref.rays), seconds,
                ref.rms_error, 100.0 * ref.rms_error / (ref.rms_radiance > 0 ? ref.rms_radiance : 1.0),
                ref.rms_radiance);
  Summary(line);

  std::string text = "# prt reference: " + std::string(TransportModeName(ro.mode)) + ", " + env->Describe() + "\n" +
                     std::to_string(mesh.vertex_count()) + "\n";
  for (const auto& c : ref.radiance) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", c.x, c.y, c.z);
    text += buf;
  }
  WriteFileAtomic(render.out + "/reference.txt", text);
  const Camera camera = ChooseCamera(mesh, render);
  Summary("camera: " + CameraArgs(camera));
  WritePng(render.out + "/reference.png", DrawVertexColors(mesh, ToFloat(ref.radiance), *env, camera, render));
  Summary("wrote " + render.out + "/reference.txt and " + render.out + "/reference.png");
  return 0;
}

}  // namespace prt
