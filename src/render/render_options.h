#pragma once
/// \file
/// What a render draws and how (docs/CLI.md, "Render options"): frames, size, the light's turn,
/// background, tone mapping, exposure, supersampling, the view, the camera and its orbit. The
/// values only, and only what drawing reads: app/render_args.h reads and checks them from the
/// command line, with the options of the job's other stages (the output folder, the cache, the
/// compressed matrices, the extra files), which it keeps beside these.

#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/tonemap.h"

namespace prt {

/// What a frame shows (--view).
enum class View {
  kRadiance,    ///< the final colour
  kIrradiance,  ///< as if every albedo were 1 and the material diffuse
  kAlbedo,      ///< the albedo alone
  kTransport,   ///< transfer coefficient transport_index in false colour
  kLight,       ///< the light as the basis keeps it
  kGlossy,      ///< a glossy material's lobe term alone
};

/// The --view word of `view` ("transport" without its index).
const char* ViewName(View view);
/// The view called `name` (ViewName's words), or nullopt.
std::optional<View> ViewFromName(const std::string& name);
/// Every view's word, in the enum's order.
std::vector<std::string> ViewNames();

struct RenderOptions {
  int frames = 120;
  /// --frame-range: the frames written, first_frame to last_frame of `frames` (app/frame_range.h);
  /// last_frame < 0: to the last. Frame 0 is drawn unwritten when the exposure is measured there.
  int first_frame = 0;
  int last_frame = -1;
  int width = 640, height = 480;
  glm::dvec3 axis{0.0, 1.0, 0.0};  ///< rotation axis of the light (world up)
  double turns = 1.0;              ///< full turns over all frames
  double start_degrees = 0.0;      ///< the light's turn at frame 0 (--start-angle)
  bool env_background = true;      ///< the environment behind the mesh, else background_color
  glm::vec3 background_color{0.0f};
  ToneCurve tonemap = ToneCurve::kAces;
  /// EV: radiance is scaled by 2^exposure before tone mapping. Empty: automatic, measured on
  /// frame 0's mesh pixels (raster/exposure.h) and printed on the run summary.
  std::optional<double> exposure;
  int ssaa = 2;
  std::optional<glm::dvec3> eye, target, up;
  std::optional<double> fov;
  View view = View::kRadiance;  ///< what to draw (View)
  int transport_index = 0;
  /// Degrees the camera turns about the target (around its up direction) over all frames: frame
  /// i is seen from the camera turned by orbit * i / frames.
  double orbit = 0.0;
};

/// The camera of `prt demo`, also used by render and reference on the embedded scene: a
/// three-quarter view of the knot with the horizon in frame.
RenderOptions WithDemoCamera(RenderOptions options);

}  // namespace prt
