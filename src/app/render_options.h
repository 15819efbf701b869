#pragma once
/// \file
/// The render options of CLI.md (frames, size, rotation, background, tone mapping, camera),
/// read and validated once for `render` and `demo`.

#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "app/args.h"
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
  ToneCurve tonemap = ToneCurve::kSrgb;
  double exposure = 0.0;           ///< EV
  int ssaa = 1;
  std::optional<glm::dvec3> eye, target, up;
  std::optional<double> fov;
  /// What to draw: radiance (the final colour), irradiance (albedo 1), albedo, transport (the
  /// coefficient transport_index in false colour) or light (the SH-reconstructed light).
  std::string view = "radiance";
  int transport_index = 0;
};

/// Reads the render options from `args`, with `defaults` for what is not given.
RenderOptions ReadRenderOptions(Args& args, const RenderOptions& defaults);

extern const char* const kRenderOptionsHelp;

}  // namespace prt
