#pragma once
/// \file
/// What the page of `prt view` asks for: one frame, as the query of `/frame` (and `/frame.png`,
/// `/command`) gives it. Every parameter is checked against what the run can draw (ViewLimits):
/// a name not listed below, a name given twice, a value that does not parse or is out of range
/// is refused with an Error naming the parameter, which the server answers with 400.
///
///   axis=X,Y,Z angle=DEGREES   the light turned by DEGREES about the axis (any non-zero axis)
///   lmax=L                     SH bands 0..L, L <= the bands computed (they nest)
///   basis=NAME mode=MODE       the transport: a basis and a transport mode the run offers
///   env=I                      the I-th environment of the command line (0: --env)
///   view=V                     radiance | irradiance | albedo | light | glossy | transport:K
///   exposure=EV tonemap=CURVE  -20..20; srgb | reinhard | aces
///   eye=, target=, up=X,Y,Z fov=DEGREES   the camera (fov 0.001..179)
///   terms=K                    the wavelet light's coefficients kept per frame, 0 (all)..6 F^2
///   size=WxH ssaa=K            1..16384 each; 1..8; W x H x K^2 at most 4096^2 samples
///   quality=Q                  still (the frame prt render draws) | interactive: drawn at ssaa 1
///                              with the basis's interactive light (basis/frame_light.h), for the
///                              frames shown while the light or the camera moves
///
/// The limits are render's (render/frame_limits.h), but for the samples of a frame: the view's
/// own budget, kMaxViewSamples.

#include <string>
#include <utility>
#include <vector>

#include "render/render_options.h"

namespace prt {

/// What the run can draw.
struct ViewLimits {
  int lmax = 2;                     ///< the SH bands computed
  std::vector<std::string> bases;   ///< bases offered (the command line's first)
  std::vector<std::string> modes;   ///< transport modes offered
  int environments = 1;
  int coefficients = 9;             ///< transport:K takes K below this
  int light_terms = 0;              ///< terms=K takes K up to this (the wavelet cube's coefficients)
  bool camera_moves = true;         ///< false: a glossy transfer computed for one eye
};

struct FrameRequest {
  RenderOptions draw;  ///< axis, start_degrees (the light's turn), view, tone curve, exposure, camera, size, ssaa
  int lmax = 2;
  std::string basis, mode;
  int env = 0;
  int light_terms = 0;  ///< the wavelet light's terms kept per frame (0: all)
  bool interactive = false;  ///< quality=interactive: ssaa 1 and the basis's interactive light
};

/// `defaults` with the parameters of `query` (name, value pairs in order) applied and checked.
FrameRequest ParseFrameRequest(const std::vector<std::pair<std::string, std::string>>& query,
                               const FrameRequest& defaults, const ViewLimits& limits);

/// The query that ParseFrameRequest reads back as `request` (every parameter written; numbers
/// with 17 significant digits).
std::string FrameQuery(const FrameRequest& request);

}  // namespace prt
