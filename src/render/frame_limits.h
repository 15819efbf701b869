#pragma once
/// \file
/// The limits of a frame's options, declared once for every road that reads them: render's and
/// demo's command line (app/render_args.cpp) and the page of prt view (view/frame_request.h), so
/// a frame one accepts the other draws. Only prt view adds a rule of its own, a budget rather
/// than a limit of the option: a frame the page asks for takes at most kMaxViewSamples samples,
/// so that the server answers every request in interactive time.

#include "raster/rasterizer.h"  // kMaxTargetSide

namespace prt {

inline constexpr int kMinFrameSide = 1;      ///< --size / size=: each side, pixels
inline constexpr int kMaxFrameSide = 16384;  ///< as large as the rasterizer's target (kMaxTargetSide)
static_assert(kMaxFrameSide <= kMaxTargetSide);
inline constexpr int kMaxSsaa = 8;           ///< --ssaa / ssaa=: K x K samples a pixel
inline constexpr double kMinFov = 1e-3;      ///< --fov / fov=: degrees
inline constexpr double kMaxFov = 179.0;
inline constexpr double kMaxExposure = 20.0; ///< --exposure / exposure=: EV, either sign
inline constexpr double kMaxAngle = 1e6;     ///< --start-angle / angle=: degrees, either sign

/// prt view's budget: width x height x ssaa^2 of a frame the page asks for, what a 4096 x 4096
/// frame takes without supersampling (its buffers about 0.5 GB).
inline constexpr double kMaxViewSamples = 4096.0 * 4096.0;

}  // namespace prt
