// prt reference: the ground truth without SH truncation (precompute/reference.h), as per-vertex
// text and as a picture drawn like frame 0 of `render`.
#include <chrono>
#include <cstdio>
#include <optional>

#include "app/commands.h"
#include "app/pipeline.h"
#include "app/precompute_shard.h"
#include "app/reference_shard.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/output_folder.h"
#include "core/text.h"
#include "farm/shard_id.h"
#include "farm/vertex_blocks.h"
#include "io/png_io.h"
#include "precompute/reference.h"
#include "precompute_io/reference_shard.h"
#include "precompute_io/transport_shard.h"
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

/// The reference the options ask for, its glossy lobe seen from `camera`'s eye.
ReferenceOptions ReferenceOptionsOf(const SceneOptions& scene, int samples, const Camera& camera) {
  ReferenceOptions ro;
  ro.mode = TransportModeFromName(scene.transport);
  ro.samples = samples;
  ro.bounces = scene.bounces;
  ro.seed = scene.seed;
  ro.material = scene.material;
  ro.eye = glm::dvec3(camera.eye);
  return ro;
}

/// `--shard`: the reference of the task's vertex block, written as its shard file into job.out
/// (nothing else there, no lock: the tasks write the folder at once).
int RunReferenceShard(const SceneOptions& scene, const RenderJobOptions& job, int samples, const ShardId& shard,
                      const std::vector<std::string>& command) {
  CreateFolder(job.out);
  const Mesh mesh = LoadSceneMesh(scene);
  const Camera camera = SceneCamera(mesh, job.draw);
  const auto env = LoadSceneEnvironment(scene);
  ReferenceOptions ro = ReferenceOptionsOf(scene, samples, camera);
  ReferenceShard s;
  s.index = shard.index;
  s.count = shard.count;
  s.command = command;
  s.key = ReferenceKey(mesh, *env, ro);
  s.vertices = mesh.vertex_count();
  // Every vertex traces the same paths: blocks of equal work are blocks of equal count.
  s.block = BlockOf(std::vector<std::uint64_t>(mesh.vertex_count(), 1), shard.index, shard.count);
  ro.block = s.block;
  Summary("shard: " + std::to_string(shard.index) + " of " + std::to_string(shard.count) + " (" + shard.source +
          "): vertices " + std::to_string(s.block.begin) + " to " + std::to_string(s.block.end - 1) + " of " +
          std::to_string(s.vertices));
  const auto t0 = std::chrono::steady_clock::now();
  const Reference ref = ComputeReference(mesh, *env, ro);
  s.rays = ref.rays;
  s.radiance.assign(ref.radiance.begin() + std::ptrdiff_t(s.block.begin), ref.radiance.begin() + std::ptrdiff_t(s.block.end));
  s.error.assign(ref.error.begin() + std::ptrdiff_t(s.block.begin), ref.error.begin() + std::ptrdiff_t(s.block.end));
  const std::string path = job.out + "/" + ShardFileName(kReferenceShardBase, shard.index, shard.count);
  WriteReferenceShard(path, s);
  Summary("reference: " + std::to_string(s.rays) + " rays" + Formatted(" [%.3f s]", SecondsSince(t0)) + "; wrote " +
          path + " (prt merge " + job.out + " writes reference.txt and reference.png once all " +
          std::to_string(shard.count) + " are written)");
  return 0;
}

}  // namespace

CommandSpec ReferenceSpec() {
  OptionGroup reference{"reference options",
                        {{"--reference-samples", "N", "directions per vertex, 2..16777216", "8192"},
                         {"--shard", "I/N",
                          "compute only vertex block I of N (0-based; blocks of whole vertices, of equal count) and "
                          "write it as DIR/reference.shard-IIIII-of-NNNNN, for a farm job: prt merge DIR then writes "
                          "reference.txt and reference.png as one run writes them. auto: I and N from a Slurm array "
                          "task (SLURM_ARRAY_TASK_ID with SLURM_ARRAY_TASK_COUNT, or the array's MIN and MAX); auto/N: "
                          "N given, I from SLURM_ARRAY_TASK_ID or a Kubernetes Indexed Job's JOB_COMPLETION_INDEX",
                          "off: every vertex"},
                         QuietOption()}};
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

int RunReference(const std::vector<std::string>& tokens) { return ReferenceCommand(tokens, nullptr); }

int ReferenceCommand(const std::vector<std::string>& tokens, const AssembledReference* assembled, bool check_only) {
  Args args("reference", tokens, ReferenceSpec());
  const SceneOptions scene = ReadSceneOptions(args);
  const int samples = args.Int("--reference-samples", 8192, 2, 1 << 24);
  const RenderJobOptions job = CompleteRenderOptions(args, ReadRenderOptions(args, PictureDefaults()), scene);
  const RenderOptions& render = job.draw;
  const auto shard_option = args.String("--shard");
  args.Finish();
  if (job.out.empty()) args.Fail("--out DIR is required");
  std::optional<ShardId> shard;
  if (shard_option) {
    try {
      shard = ParseShard(*shard_option);
    } catch (const Error& e) {
      args.Fail(e.what());
    }
  }
  if (check_only) return 0;
  if (shard) return RunReferenceShard(scene, job, samples, *shard, ShardCommand("reference", tokens));
  OutputFolder folder(job.out, {"reference", {"reference.txt", "reference.png"}, job.replace});

  const Mesh mesh = LoadSceneMesh(scene, &folder);
  const Camera camera = SceneCamera(mesh, render);
  const auto env = LoadSceneEnvironment(scene, &folder);
  const ReferenceOptions ro = ReferenceOptionsOf(scene, samples, camera);
  const auto t0 = std::chrono::steady_clock::now();
  Reference ref;
  if (assembled) {
    if (assembled->key != ReferenceKey(mesh, *env, ro))
      throw Error("the shards were made from another mesh, light or options than those read now (expected the same "
                  "mesh, environment and options as the shards' tasks)");
    ref = assembled->reference;
    Summary("reference: assembled from " + std::to_string(assembled->count) + " shards (" +
            std::to_string(ref.radiance.size()) + " vertices), as one run computes it");
  } else {
    ref = ComputeReference(mesh, *env, ro);
  }
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
