// RenderJob (pipeline.h): the main job of `render` and `demo`, stage by stage.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/pipeline.h"
#include "app/render_args.h"
#include "app/render_video.h"
#include "app/seen_ringing.h"
#include "bases/list.h"
#include "basis/cache_plan.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/text.h"
#include "precompute/shade.h"
#include "precompute_io/transport_txt.h"
#include "render/render_frames.h"
#include "render/seen_vertices.h"

namespace prt {
namespace {

/// Frame files in the folder that this run did not write and prt's list did not name (written
/// by someone else, or by a prt older than the list): never removed, but worth a word.
std::size_t ForeignFrames(OutputFolder& folder) {
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder.dir(), ec)) {
    const std::string name = entry.path().filename().string();
    n += IsFrameName(name) && !folder.Wrote(name);
  }
  return n;
}

/// Says how many frame files in `folder` this run did not write and prt has no record of
/// (after FinishOutputs, which removes those it has): they are left as they are.
void NoteForeignFrames(OutputFolder& folder) {
  if (const std::size_t n = ForeignFrames(folder))
    Summary("note: " + std::to_string(n) + " frame file" + (n > 1 ? "s" : "") + " in " + folder.dir() +
            " not written by this run " + (n > 1 ? "were" : "was") + " left untouched (prt has no record of writing " +
            (n > 1 ? "them)" : "it)"));
}

/// What a render writes into its folder, known before any work: the frames, and the video and
/// --vertex-radiance file when they lie in it.
OutputPlan RenderPlan(const RenderJobOptions& r) {
  // A --frame-range run writes a part of the folder: its frames, beside the other ranges.
  const bool range = r.draw.first_frame > 0 || r.draw.last_frame >= 0;
  OutputPlan plan{"render", {}, r.replace, range};
  const int last = r.draw.last_frame < 0 ? r.draw.frames - 1 : r.draw.last_frame;
  for (int i = r.draw.first_frame; i <= last; ++i) plan.names.push_back(FrameName(i, r.draw.frames));
  for (const std::string& file : {r.video.path, r.vertex_radiance})
    if (!file.empty() && LiesIn(file, r.out)) plan.names.push_back(std::filesystem::path(file).filename().string());
  return plan;
}

/// Frame 0's per-vertex radiance toward the camera, its light turned to frame 0's angle
/// (FrameAngle: --start-angle), as RenderFrames shades it, to the --vertex-radiance file `path`
/// (precompute_io/transport_txt.h: three rows per face of the mesh as read, --max-edge's split
/// vertices left out): one of the folder's outputs when it lies there; else written beside it
/// under a temporary name, returned to be renamed into place when the run has succeeded.
std::unique_ptr<SingleFileOutput> WriteVertexRadiance(const Mesh& mesh, FrameLight& light, const Camera& camera,
                                                      const RenderOptions& render, const std::string& path,
                                                      OutputFolder& folder) {
  const glm::dvec3 eye(camera.eye);
  light.Turn(FrameAngle(render, 0));
  const std::string text = FormatVertexRadianceTxt(mesh, light.Shade(mesh, true, &eye));
  const std::size_t written = FileVertexCount(mesh), added = mesh.vertex_count() - written;
  Summary("vertex radiance: frame 0's linear RGB radiance of " + std::to_string(written) +
          " vertices toward the camera, three rows per face of the mesh as read" +
          (added ? " (the " + std::to_string(added) + " vertices --max-edge added are not in it)" : "") + ", in " +
          path);
  if (LiesIn(path, folder.dir())) {
    WriteFileAtomic(folder.Output(std::filesystem::path(path).filename().string()), text);
    return nullptr;
  }
  auto outside = std::make_unique<SingleFileOutput>(path);
  outside->Write(text);
  return outside;
}

/// The run-summary note on the pixels whose radiance came out negative, with the advice that
/// holds for the light the frames used. When what they show of it goes negative (no window, or
/// hann or lanczos), the auto window removes that. When it does not (the auto window, or none
/// needed), no window can help: the transport made them. The transfer matrices of a glossy
/// --orbit truncate light x visibility x cosine to lmax before the lobe (the fixed camera's
/// vectors do not); otherwise the shadows' Monte Carlo estimate undershoots where --samples is
/// low (both measured on the demo scene under sky:sun=1000 and 100000 with the auto window:
/// none with a fixed camera, none at --samples 64 where --samples 8 made 28 pixels).
std::string RingingNote(std::size_t pixels, const ShRgb& light, const SceneOptions& scene, View view,
                        bool matrices) {
  const std::string note = "ringing: " + std::to_string(pixels) +
                           " pixels over all frames had negative radiance (SH ringing), clamped to 0; ";
  if (FindSeenRinging(light, scene.material, view).rings) return note + "--window auto reduces it";
  const std::string window = scene.window == "auto"           ? " (the light is already windowed: --window auto)"
                             : scene.window == kDefaultWindow ? " (with the default window: the light line says which)"
                             : scene.window == "none"         ? " without a window"
                                                              : " with --window " + scene.window;
  const std::string lmax = std::to_string(scene.lmax);
  const std::string cause =
      matrices ? "the transfer matrices of --orbit truncate light x visibility x cosine to lmax " + lmax +
                     " before the glossy lobe (a fixed camera, without --orbit, has exact vectors instead)"
      : scene.transport != "unshadowed"
          ? "the shadows are estimated with " + std::to_string(scene.samples) + " rays per vertex (more --samples reduce them)"
          : "the transport's own truncation to lmax " + lmax;
  return note + "what the frames show of the light is non-negative" + window + ", so no window removes them: " + cause;
}

}  // namespace

RenderInputs LoadRenderInputs(const SceneOptions& scene, const RenderJobOptions& job, OutputFolder* folder) {
  const RenderOptions& render = job.draw;
  RenderInputs in;
  // Mesh and camera first: a camera that cannot see is refused before any light is loaded.
  in.mesh = LoadSceneMesh(scene, folder);
  in.camera = SceneCamera(in.mesh, render);

  // A glossy surface seen from a moving camera needs transfer matrices: their memory is
  // checked before the light is loaded.
  // (Views that show no lobe do not need them.)
  in.matrices =
      scene.material.glossy && render.orbit != 0.0 && (render.view == View::kRadiance || render.view == View::kGlossy);
  in.transport_options = TransportOptionsOf(scene);
  scene.basis->CheckMemory(in.mesh, in.transport_options, in.matrices);

  in.env = LoadSceneEnvironment(scene, folder);
  // The light view draws the light alone: no transport, unless --vertex-radiance writes the
  // vertices' radiance.
  in.transport = render.view != View::kLight || !job.vertex_radiance.empty();
  // The vertices the frames show take --samples directions, the others --hidden-samples; with
  // --vertex-radiance, which writes every vertex, all of them are computed as seen ones.
  const bool fewer = scene.transport != "unshadowed" && scene.hidden_samples != scene.samples;
  if (in.transport && fewer && job.vertex_radiance.empty())
    in.transport_options.seen = SeenVertices(in.mesh, in.camera, render);
  if (fewer && !job.vertex_radiance.empty())
    Summary("vertex radiance: every vertex computed as one the camera sees (--hidden-samples " +
            std::to_string(scene.hidden_samples) + " not used): --vertex-radiance writes them all, and none may depend "
            "on the camera");
  return in;
}

void RenderJob(const SceneOptions& scene, const RenderJobOptions& job, const ShardedTransport& sharded) {
  const RenderOptions& render = job.draw;  // all that the frame loop reads
  const OutputPlan plan = RenderPlan(job);
  OutputFolder folder(job.out, plan);
  const CachePlan cache = PlanCache(job.cache, &folder, scene.basis->CacheName(), Bases());
  // The other bases' caches stay in the folder: a run of one basis does not remove another's.
  for (const Basis* other : Bases())
    if (other != scene.basis) folder.OutputInPlace(other->CacheName());

  const RenderInputs in = LoadRenderInputs(scene, job, &folder);
  const Mesh& mesh = in.mesh;
  const Camera& camera = in.camera;
  const bool matrices = in.matrices, transport = in.transport;
  const auto& env = in.env;
  const ShRgb light = ComputeLight(*env, scene, render.view);
  // The transport in its basis (basis/basis.h), and the light each frame turns for it.
  const BasisInputs inputs{mesh,     in.transport_options, scene.samples_from_rule, scene.lmax_why, scene.own(),
                           render.axis, job.cpca,          *env,                    &camera,        cache,
                           matrices,    sharded};
  if (!transport)
    Summary("transport: none computed (--view light draws the light as the basis keeps it, not the mesh's transport)");
  const std::unique_ptr<PreparedBasis> basis = transport ? scene.basis->Prepare(inputs) : scene.basis->PrepareLight(inputs);
  const std::unique_ptr<FrameLight> light_of_frames =
      basis->Light(*env, light, render.axis, scene.basis->LightTerms(scene.own()), LightQuality::kStill);
  FrameLight& frame_light = *light_of_frames;
  std::unique_ptr<SingleFileOutput> radiance_outside;
  if (!job.vertex_radiance.empty())
    radiance_outside = WriteVertexRadiance(mesh, frame_light, camera, render, job.vertex_radiance, folder);

  RenderVideo video(job.video, render, folder);
  const FrameStats stats = RenderFrames(mesh, frame_light, *env, camera, render, folder, video.writer());
  if (stats.legend_left_out)
    Summary("legend: left out, a " + std::to_string(render.width) + "x" + std::to_string(render.height) +
            " frame is too small to hold it readably");
  if (!render.exposure && render.view != View::kTransport)
    ReportAutoExposure(stats.exposure, render.first_frame > 0 ? "frame 0's mesh pixels (drawn, not written: the range "
                                                                "starts later)"
                                                              : "frame 0's mesh pixels");
  Summary("frames: " + std::to_string(stats.frames) + " of " + std::to_string(render.width) + "x" +
          std::to_string(render.height) + " in " + folder.dir() + "/" +
          Formatted(" [draw %.3f s, waiting for PNG encoding %.3f s]", stats.draw_seconds, stats.encode_seconds));
  if (stats.negative_pixels > 0 && scene.basis->Traits().windowed_light)
    Summary(RingingNote(stats.negative_pixels, light, scene, render.view, matrices));
  if (stats.nan_pixels > 0) Summary("warning: " + std::to_string(stats.nan_pixels) + " NaN pixels set to 0");
  if (const std::string line = video.Finish(); !line.empty()) Summary(line);
  FinishOutputs(folder);
  // The files outside the folder last: a run that failed before here left the earlier ones.
  video.Commit();
  if (radiance_outside) radiance_outside->Commit();
  // The other ranges' frames are not foreign to a range: they may be listed only once theirs end.
  if (!plan.part) NoteForeignFrames(folder);
}

}  // namespace prt
