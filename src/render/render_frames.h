#pragma once
/// \file
/// The frame loop of `render` and `demo`. For frame i of N the light is turned by
///     a_i = start + 2 pi * turns * i / N   (start: --start-angle, 0 by default)
/// about the axis (from the absolute angle: no drift) and the camera by orbit * i / N degrees
/// about its target (raster/camera.h, Orbit), the vertices are shaded by their transport in its
/// basis (basis/frame_light.h), the mesh is rasterized over the environment
/// turned by the same rotation, tone-mapped, and written as DIR/frame_NNNN.png (four digits, more
/// when N needs them, so names sort in frame order), and appended to the video if one is asked
/// for. Encoding frame i overlaps drawing i+1.

#include <cstddef>
#include <string>
#include <vector>

#include "basis/frame_light.h"
#include "core/output_folder.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "raster/camera.h"
#include "raster/rasterizer.h"
#include "raster/tonemap.h"
#include "render/render_options.h"
#include "video/video_writer.h"

namespace prt {

struct FrameStats {
  int frames = 0;
  double exposure = 0.0;            ///< the EV used (measured when --exposure auto)
  std::size_t negative_pixels = 0;  ///< summed over frames: pixels whose radiance was < 0 (ringing)
  std::size_t nan_pixels = 0;
  double draw_seconds = 0, encode_seconds = 0;
  bool legend_left_out = false;     ///< transport view: the frame is too small for a readable legend
};

/// The largest |T_index| over the first `vertices` vertices (FrameLight::Coefficient): the ends
/// of the transport view's colour scale.
double TransportViewScale(const FrameLight& light, std::size_t vertices, int index);

/// The camera of the options: what they give, the rest from automatic framing of the mesh
/// (raster/camera.h, fitted to its projected vertices), clip planes fitted to the mesh. When no
/// --up was given and world up is parallel to the view, a perpendicular up is chosen and
/// `note` (if given) says so.
Camera ChooseCamera(const Mesh& mesh, const RenderOptions& options, std::string* note = nullptr);

/// What a frame loop keeps between frames: the rasterizer's buffers and the per-vertex colours,
/// so that after the first frame drawing allocates nothing.
class FrameDrawer {
 public:
  FrameDrawer() : rasterizer_(own_) {}
  /// Draws with `rasterizer`'s buffers instead of its own.
  explicit FrameDrawer(Rasterizer& rasterizer) : rasterizer_(rasterizer) {}
  /// The frame RasterizeFrame (below) draws. With `tone` it is tone mapped into `*toned` band by
  /// band as it is drawn and the linear frame is left out (RasterOptions::tone_map,
  /// keep_linear): the result then has only RasterImage::tone_counts, what the tone mapping
  /// repaired. Valid until the next Draw.
  const RasterImage& Draw(const Mesh& mesh, FrameLight& light, const Environment& env, const Camera& camera,
                          const RenderOptions& options, double angle, double view_scale,
                          const ToneMapOptions* tone = nullptr, Image8* toned = nullptr);

 private:
  Rasterizer own_;
  Rasterizer& rasterizer_;
  std::vector<glm::vec3> colors_, added_;
};

/// The linear frame with `light` turned by `angle` radians (FrameLight::Turn): shading,
/// rasterizing over the turned environment (the teaching view transport:K over a neutral grey
/// instead, its colours scaled by `view_scale`, TransportViewScale; the light view over the
/// light as the basis keeps it). `rasterizer` keeps its buffers; the result is valid until its
/// next call.
const RasterImage& RasterizeFrame(Rasterizer& rasterizer, const Mesh& mesh, FrameLight& light, const Environment& env,
                                  const Camera& camera, const RenderOptions& options, double angle, double view_scale);

/// How the frames of `options` are tone mapped at `exposure_ev` (the transport view: passed
/// through unchanged).
ToneMapOptions FrameToneMap(const RenderOptions& options, double exposure_ev);
/// What a tone-mapped frame gets drawn on it: the transport view's legend, from -view_scale to
/// +view_scale.
void FinishFrame(Image8& image, const RenderOptions& options, double view_scale);

/// A rasterized frame tone mapped with `exposure_ev` (the transport view: passed through, with
/// its legend from -view_scale to +view_scale).
ToneMapped ToneMapFrame(const RasterImage& frame, const RenderOptions& options, double exposure_ev, double view_scale);

/// One frame, RasterizeFrame then ToneMapFrame (for tests: RenderFrames does the same once per
/// frame, with the scale computed once).
ToneMapped DrawFrame(Rasterizer& rasterizer, const Mesh& mesh, FrameLight& light, const Environment& env,
                     const Camera& camera, const RenderOptions& options, double angle, double exposure_ev);

/// Renders the frames (all, or options.first_frame to last_frame) into `folder`, each named
/// through folder.Output(), and hands each to `video` (if given) once its PNG is encoded; the
/// automatic exposure (raster/exposure.h) is measured on frame 0 (drawn and not written when the
/// range starts later) and used for every frame.
FrameStats RenderFrames(const Mesh& mesh, FrameLight& light, const Environment& env, const Camera& camera,
                        const RenderOptions& options, OutputFolder& folder, VideoWriter* video = nullptr);

/// The light's turn at frame `i` of `options.frames`, in radians, from the absolute angle:
///     a_i = start_degrees * pi / 180 + 2 pi * turns * i / frames
double FrameAngle(const RenderOptions& options, int i);

/// The file name of frame `i` of `count`: frame_0000.png ..., with as many digits as count - 1
/// needs (at least four), so that the names sort in frame order.
std::string FrameName(int i, int count);

/// True for a name FrameName gives (frame_, digits, .png), with any number of digits; with
/// `any_case`, its letters in either case too (FRAME_0001.PNG).
bool IsFrameName(const std::string& name, bool any_case = false);

}  // namespace prt
