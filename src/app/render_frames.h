#pragma once
/// \file
/// The frame loop of `render` and `demo`. For frame i of N the light is turned by
///     a_i = 2 pi * turns * i / N
/// about the axis (sh/axis_rotation.h, built from the absolute angle: no drift), the vertices are
/// shaded by their transport (precompute/shade.h), the mesh is rasterized over the environment
/// turned by the same rotation, tone-mapped, and written as DIR/frame_NNNN.png. Encoding frame
/// i overlaps drawing frame i+1.

#include <cstddef>
#include <string>

#include "app/render_options.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "raster/camera.h"
#include "raster/rasterizer.h"
#include "raster/tonemap.h"
#include "sh/axis_rotation.h"
#include "sh/coeffs.h"

namespace prt {

struct FrameStats {
  int frames = 0;
  std::size_t negative_pixels = 0;  ///< summed over frames: pixels whose radiance was < 0 (ringing)
  std::size_t nan_pixels = 0;
  double draw_seconds = 0, encode_seconds = 0;
  std::size_t stale_frames = 0;     ///< older frame files beyond the last one, left untouched
};

/// The camera of the options: automatic framing of the mesh bounds, overridden by what the
/// options give, with clip planes fitted to the mesh.
Camera ChooseCamera(const Mesh& mesh, const RenderOptions& options);

/// Draws one frame with the light turned by `angle` radians by `rotation` (about the options'
/// axis, built once per run for the transport's lmax): shading, rasterizing over the turned
/// environment, tone mapping. `rasterizer` keeps its buffers.
ToneMapped DrawFrame(Rasterizer& rasterizer, const Mesh& mesh, const Transport& transport, const ShRgb& light,
                     const AxisRotation& rotation, const Environment& env, const Camera& camera,
                     const RenderOptions& options, double angle);

/// Renders all frames into options.out (created if missing).
FrameStats RenderFrames(const Mesh& mesh, const Transport& transport, const ShRgb& light,
                        const Environment& env, const Camera& camera, const RenderOptions& options);

/// The file name of frame `i`: frame_0000.png, ...
std::string FrameName(int i);

}  // namespace prt
