// RenderJob (pipeline.h): the main job of `render` and `demo`, stage by stage.
#include <cstdio>
#include <filesystem>
#include <regex>

#include "app/pipeline.h"
#include "core/log.h"
#include "raster/annotate.h"
#include "raster/exposure.h"

namespace prt {
namespace {

std::string Format(const char* fmt, double a, double b = 0.0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

/// Frame files in the folder that this run did not write and prt's list did not name (written
/// by someone else, or by a prt older than the list): never removed, but worth a word.
std::size_t ForeignFrames(OutputFolder& folder) {
  static const std::regex pattern("frame_[0-9]+\\.png");
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder.dir(), ec)) {
    const std::string name = entry.path().filename().string();
    n += std::regex_match(name, pattern) && !folder.Wrote(name);
  }
  return n;
}

}  // namespace

void RenderJob(const SceneOptions& scene, const RenderOptions& render, OutputFolder& folder) {
  const CachePlan cache = PlanCache(render.cache, &folder);

  // Mesh and camera first: a camera that cannot see is refused before any light is loaded.
  const Mesh mesh = LoadSceneMesh(scene, &folder);
  std::string up_note;
  const Camera camera = ChooseCamera(mesh, render, &up_note);
  Summary("camera: " + CameraArgs(camera) + (up_note.empty() ? "" : " (" + up_note + ")"));

  const auto env = LoadSceneEnvironment(scene, &folder);
  const ShRgb light = ComputeLight(*env, scene);
  const Transport transport = ComputeSceneTransport(mesh, scene, cache);
  const AxisRotation rotation(render.axis, transport.lmax);
  Summary("rotation: " + rotation.Describe() + "; only the " + std::to_string(CoeffCount(transport.lmax)) +
          " coefficients the transport has are turned");

  if (render.view == "transport" &&
      !LayoutDivergingLegend(render.width, render.height, TransportViewScale(transport, render.transport_index),
                             "T" + std::to_string(render.transport_index)))
    Summary("legend: left out, a " + std::to_string(render.width) + "x" + std::to_string(render.height) +
            " frame is too small to hold it readably");
  const FrameStats stats = RenderFrames(mesh, transport, light, *env, camera, render, folder);
  if (!render.exposure && render.view != "transport")
    Summary(Format("exposure: auto -> %.1f EV, measured on frame 0's mesh pixels (--exposure %.1f repeats it)",
                   stats.exposure, stats.exposure) +
            AutoExposureLimitNote(stats.exposure));
  Summary("frames: " + std::to_string(stats.frames) + " of " + std::to_string(render.width) + "x" +
          std::to_string(render.height) + " in " + folder.dir() + "/" +
          Format(" [draw %.3f s, waiting for PNG encoding %.3f s]", stats.draw_seconds, stats.encode_seconds));
  if (stats.negative_pixels > 0)
    Summary("ringing: " + std::to_string(stats.negative_pixels) +
            " pixels over all frames had negative radiance (SH ringing), clamped to 0; --window auto reduces it");
  if (stats.nan_pixels > 0) Summary("warning: " + std::to_string(stats.nan_pixels) + " NaN pixels set to 0");
}

void NoteForeignFrames(OutputFolder& folder) {
  if (const std::size_t n = ForeignFrames(folder))
    Summary("note: " + std::to_string(n) + " frame file" + (n > 1 ? "s" : "") + " in " + folder.dir() +
            " not written by this run " + (n > 1 ? "were" : "was") + " left untouched (prt has no record of writing " +
            (n > 1 ? "them)" : "it)"));
}

}  // namespace prt
