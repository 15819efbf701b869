#pragma once
/// \file
/// The render options of CLI.md (frames, size, rotation, background, tone mapping, camera, the
/// transport cache): their table entries, documented with the command's own defaults, and their
/// reader. Every value, the camera included, is checked here, before any file is loaded.

#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "app/args.h"
#include "app/scene_options.h"
#include "raster/tonemap.h"

namespace prt {

struct RenderOptions {
  int frames = 120;
  int width = 640, height = 480;
  std::string out = "out/render";
  glm::dvec3 axis{0.0, 1.0, 0.0};  ///< rotation axis of the light (world up)
  double turns = 1.0;              ///< full turns over all frames
  bool env_background = true;      ///< the environment behind the mesh, else background_color
  glm::vec3 background_color{0.0f};
  ToneCurve tonemap = ToneCurve::kAces;
  /// EV: radiance is scaled by 2^exposure before tone mapping. Empty: automatic, measured on
  /// frame 0's mesh pixels (raster/exposure.h) and printed on the run summary.
  std::optional<double> exposure;
  int ssaa = 2;
  std::optional<glm::dvec3> eye, target, up;
  std::optional<double> fov;
  /// What to draw: radiance (the final colour), irradiance (albedo 1), albedo, transport (the
  /// coefficient transport_index in false colour), light (the SH-reconstructed light) or glossy
  /// (a glossy material's lobe term alone).
  std::string view = "radiance";
  int transport_index = 0;
  /// The transport cache to reuse and update: empty for "DIR/transport.cache", "none" for none.
  std::string cache;
  /// Degrees the camera turns about the target (around its up direction) over all frames: frame
  /// i is seen from the camera turned by orbit * i / frames.
  double orbit = 0.0;
  /// Where frame 0's per-vertex linear radiance is written (io/transport_txt.h); empty: nowhere.
  std::string vertex_radiance;
  /// The frames also as one video file (app/render_video.h); empty: none. Its rate in frames
  /// per second, and the ffmpeg program for .mp4 and .webm (found when the options are read).
  std::string video;
  double fps = 30.0;
  std::string ffmpeg;
};

/// The camera of `prt demo`, also used by render and reference on the embedded scene: a
/// three-quarter view of the knot with the horizon in frame.
RenderOptions WithDemoCamera(RenderOptions options);

/// Every render option in help order: what `render` and `demo` take.
const std::vector<std::string>& AllRenderOptionNames();

/// The table entries of the render options in `names`, documented with `defaults`' values.
OptionGroup RenderOptionGroup(const RenderOptions& defaults, const std::vector<std::string>& names,
                              const std::string& title = "render options");

/// Reads the render options the command's table lists, with `defaults` for what is not given.
RenderOptions ReadRenderOptions(Args& args, const RenderOptions& defaults);

/// Checks what depends on both option sets (a transport coefficient the lmax does not have)
/// and gives the embedded scene the demo's camera when no camera option was given.
RenderOptions CompleteRenderOptions(Args& args, RenderOptions render, const SceneOptions& scene);

}  // namespace prt
