// prt reference: the ground truth without SH truncation (precompute/reference.h), as per-vertex
// text and as a picture drawn like frame 0 of `render`.
#include <chrono>
#include <cstdio>

#include "app/commands.h"
#include "app/pipeline.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "io/png_io.h"
#include "precompute/reference.h"
#include "report/report_image.h"

namespace prt {
namespace {

const std::vector<std::string> kSceneNames = {"--mesh",    "--env",  "--transport", "--bounces",        "--albedo",
                                              "--material", "--seed", "--threads",   "--games202-faces", "--max-edge"};
const std::vector<std::string> kPictureNames = {"--out", "--replace", "--size", "--background", "--tonemap", "--exposure",
                                                "--ssaa", "--eye", "--target", "--up", "--fov"};

RenderJobOptions PictureDefaults() {
  RenderJobOptions o;
  o.out.clear();  // required
  return o;
}

}  // namespace

CommandSpec ReferenceSpec() {
  OptionGroup reference{"reference options",
                        {{"--reference-samples", "N", "directions per vertex, 2..16777216", "8192"}, QuietOption()}};
  return {"prt reference [scene options] [picture options] --out DIR",
          "Ground truth without SH truncation: each vertex's outgoing radiance, the environment integrated directly "
          "against max(0, n.w) V(w) albedo/pi by importance-sampled, randomly shifted lattice directions (plus "
          "per-vertex path tracing of --bounces bounces for --transport interreflection). A glossy --material adds "
          "its lobe toward the picture camera's eye, sampled by multiple importance sampling of the environment and "
          "the lobe (balance heuristic). Its own error is estimated from two independent halves.\n\nWrites "
          "DIR/reference.txt (the vertex count, then one `R G B` line per vertex) and DIR/reference.png (the mesh "
          "drawn with these colours by the rasterizer, camera and tone mapping of render's frame 0; with automatic "
          "exposure the EV is measured on this picture, so pass render's printed --exposure to compare the two "
          "pixel by pixel).",
          {SceneOptionGroup(SceneOptions{}, kSceneNames), RenderOptionGroup(PictureDefaults(), kPictureNames, "picture options"),
           reference}};
}

int RunReference(const std::vector<std::string>& tokens) {
  Args args("reference", tokens, ReferenceSpec());
  const SceneOptions scene = ReadSceneOptions(args);
  const int samples = args.Int("--reference-samples", 8192, 2, 1 << 24);
  const RenderJobOptions job = CompleteRenderOptions(args, ReadRenderOptions(args, PictureDefaults()), scene);
  const RenderOptions& render = job.draw;
  args.Finish();
  if (job.out.empty()) args.Fail("--out DIR is required");
  OutputFolder folder(job.out, {"reference", {"reference.txt", "reference.png"}, job.replace});

  const Mesh mesh = LoadSceneMesh(scene, &folder);
  const Camera camera = SceneCamera(mesh, render);
  const auto env = LoadSceneEnvironment(scene, &folder);
  ReferenceOptions ro;
  ro.mode = TransportModeFromName(scene.transport);
  ro.samples = samples;
  ro.bounces = scene.bounces;
  ro.seed = scene.seed;
  ro.material = scene.material;
  ro.eye = glm::dvec3(camera.eye);
  const auto t0 = std::chrono::steady_clock::now();
  const Reference ref = ComputeReference(mesh, *env, ro);
  const double seconds = SecondsSince(t0);
  char line[512];
  std::snprintf(line, sizeof line,
                "reference: %s, %s%s, %d importance-sampled lattice directions per vertex in two halves, %llu "
                "rays [%.3f s]; estimated RMS error %.3g (%.3g%% of the RMS radiance %.3g)",
                TransportModeName(ro.mode), ro.material.Name().c_str(),
                ro.material.glossy ? " seen from the picture's eye (environment and lobe by MIS)" : "",
                2 * (samples / 2), static_cast<unsigned long long>(ref.rays), seconds, ref.rms_error,
                100.0 * ref.rms_error / (ref.rms_radiance > 0 ? ref.rms_radiance : 1.0), ref.rms_radiance);
  Summary(line);

  std::string text = std::to_string(mesh.vertex_count()) + "\n";
  for (const auto& c : ref.radiance) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", c.x, c.y, c.z);
    text += buf;
  }
  WriteFileAtomic(folder.Output("reference.txt"), text);
  double exposure = 0.0;
  WritePng(folder.Output("reference.png"), DrawVertexColors(mesh, ToFloat(ref.radiance), *env, camera, render, &exposure));
  if (!render.exposure) ReportAutoExposure(exposure, "this picture");
  FinishOutputs(folder);
  Summary("wrote " + job.out + "/reference.txt and " + job.out + "/reference.png");
  return 0;
}

}  // namespace prt
