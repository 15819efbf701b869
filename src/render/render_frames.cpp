#include "render/render_frames.h"

#include "core/constants.h"
#include "render/frame_writer.h"

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/text.h"
#include "geometry/mesh_ops.h"
#include "io/image_load.h"
#include "io/png_io.h"
#include "raster/annotate.h"
#include "raster/exposure.h"
#include "sh/rotation.h"

namespace prt {
namespace {

/// The transport view needs coefficient `index` of every vertex; a basis without them, or an
/// index beyond them, is refused (render_args refuses both before any work).
void CheckViewCoefficient(const FrameLight& light, int index) {
  if (light.ViewCoefficients() == 0)
    throw Error("--view transport shows SH coefficients; this transport has none (--basis sh)");
  if (index < 0 || index >= light.ViewCoefficients())
    throw Error("--view transport:" + std::to_string(index) + ": the transport has " +
                std::to_string(light.ViewCoefficients()) + " coefficients per vertex (internal)");
}

/// Per-vertex colours of the chosen view into `colors`; `scale` is TransportViewScale for the
/// transport view.
void ViewColors(const Mesh& mesh, const FrameLight& light, const RenderOptions& o, double scale,
                const glm::dvec3& eye, std::vector<glm::vec3>& colors) {
  if (o.view == View::kIrradiance) return light.ShadeInto(mesh, false, nullptr, colors);
  if (o.view == View::kAlbedo) {
    colors = mesh.albedo;
    return;
  }
  if (o.view == View::kGlossy) {
    colors = light.Glossy(mesh, &eye);
    return;
  }
  colors.resize(mesh.vertex_count());
  if (o.view == View::kLight) {
    for (std::size_t v = 0; v < colors.size(); ++v) colors[v] = light.Kept(glm::dvec3(mesh.normals[v]));
    return;
  }
  if (o.view == View::kTransport) {
    CheckViewCoefficient(light, o.transport_index);
    const double s = scale > 0 ? scale : 1.0;
    for (std::size_t v = 0; v < colors.size(); ++v) {
      // Palette colours are display values: decode them so the sRGB tone curve restores them.
      const glm::vec3 c = DivergingColor(light.Coefficient(v, o.transport_index) / s);
      colors[v] = glm::vec3(SrgbToLinear(c.x), SrgbToLinear(c.y), SrgbToLinear(c.z));
    }
    return;
  }
  light.ShadeInto(mesh, true, &eye, colors);
}

/// A perpendicular up for a view along world up: looking down, the image's top shows -Z (the
/// far side of a scene facing +Z); looking up, +Z.
glm::vec3 UpAcross(const glm::vec3& view) { return view.y < 0.f ? glm::vec3(0, 0, -1) : glm::vec3(0, 0, 1); }

}  // namespace

double FrameAngle(const RenderOptions& o, int i) {
  return o.start_degrees * (kPi / 180.0) + 2.0 * kPi * o.turns * double(i) / double(o.frames);
}

std::string FrameName(int i, int count) {
  int digits = 4;
  for (long long limit = 10000; limit < count; limit *= 10) ++digits;
  char buf[48];
  std::snprintf(buf, sizeof buf, "frame_%0*d.png", digits, i);
  return buf;
}

bool IsFrameName(const std::string& name, bool any_case) {
  const std::string prefix = "frame_", suffix = ".png";
  if (name.size() < prefix.size() + 1 + suffix.size()) return false;
  const auto same = [any_case](char a, char b) {
    return a == b || (any_case && std::tolower(static_cast<unsigned char>(a)) == b);
  };
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (!same(name[i], prefix[i])) return false;
  const std::size_t digits_end = name.size() - suffix.size();
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (!same(name[digits_end + i], suffix[i])) return false;
  return AllDigits(std::string_view(name).substr(prefix.size(), digits_end - prefix.size()));
}

Camera ChooseCamera(const Mesh& mesh, const RenderOptions& o, std::string* note) {
  const Bounds3 b = MeshBounds(mesh);
  const float aspect = float(o.width) / float(o.height);
  // Fitted only when the eye is not given (a given eye decides the view; the target then
  // defaults to the mesh's centre).
  Camera c = o.eye ? Camera{} : FramePoints(mesh.positions, aspect, o.fov ? float(*o.fov) : Camera{}.fov_deg);
  if (o.eye) c.eye = glm::vec3(*o.eye);
  if (o.target) c.target = glm::vec3(*o.target);
  else if (o.eye) c.target = 0.5f * (b.lo + b.hi);
  if (o.up) c.up = glm::vec3(*o.up);
  if (o.fov) c.fov_deg = float(*o.fov);
  const glm::vec3 view = c.target - c.eye;
  if (!o.up && glm::length(view) > 0.f &&
      glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-6f) {
    const glm::vec3 world_up = c.up;
    c.up = UpAcross(view);
    if (note) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "up %g,%g,%g is parallel to the view, so up %g,%g,%g is used", double(world_up.x),
                    double(world_up.y), double(world_up.z), double(c.up.x), double(c.up.y), double(c.up.z));
      *note = buf;
    }
  }
  c = FitClipPlanes(c, b.lo, b.hi);
  CheckCamera(c);
  return c;
}

const RasterImage& FrameDrawer::Draw(const Mesh& mesh, FrameLight& light, const Environment& env, const Camera& camera,
                                     const RenderOptions& o, double angle, double view_scale, const ToneMapOptions* tone,
                                     Image8* toned) {
  // The light, and the environment behind the mesh, turned by R: L'(d) = L(R^T d).
  light.Turn(angle);
  // A textured mesh is shaded per pixel: the texture's albedo times the interpolated irradiance
  // (the vertex colour without albedo), plus a glossy lobe, which the albedo does not scale.
  const bool textured = mesh.textured() && (o.view == View::kRadiance || o.view == View::kAlbedo);
  added_.clear();
  if (!textured) {
    ViewColors(mesh, light, o, view_scale, glm::dvec3(camera.eye), colors_);
  } else if (o.view == View::kAlbedo) {
    colors_.assign(mesh.vertex_count(), glm::vec3(1.f));
  } else {
    const glm::dvec3 eye(camera.eye);
    light.ShadeInto(mesh, false, nullptr, colors_);
    if (light.HasGlossy()) added_ = light.Glossy(mesh, &eye);
  }
  RasterTexturing texturing{&mesh.corner_uv, &mesh.triangle_texture, &mesh.textures, added_.empty() ? nullptr : &added_};
  RasterOptions ro;
  if (textured) ro.texturing = &texturing;
  ro.ssaa = o.ssaa;
  ro.background.color = o.background_color;
  ro.tone_map = tone;
  ro.tone_mapped = toned;
  ro.keep_linear = false;  // with tone mapping asked for, only the 8-bit frame is needed
  if (o.view == View::kTransport) {
    ro.background.color = glm::vec3(static_cast<float>(SrgbToLinear(0.5f)));  // neutral grey: no colour to confuse with T
  } else if (o.view == View::kLight) {
    ro.background.radiance = [&light](const glm::vec3& d) { return light.Kept(glm::dvec3(d)); };
  } else if (o.env_background) {
    const glm::mat3 inverse(glm::transpose(AxisAngle(glm::normalize(o.axis), angle)));
    ro.background.radiance = [&env, inverse](const glm::vec3& d) { return glm::vec3(env.Radiance(glm::dvec3(inverse * d))); };
  }
  return rasterizer_.Draw(camera, o.width, o.height, mesh.positions, mesh.triangles, colors_, ro);
}

const RasterImage& RasterizeFrame(Rasterizer& rasterizer, const Mesh& mesh, FrameLight& light,
                                  const Environment& env, const Camera& camera, const RenderOptions& o, double angle,
                                  double view_scale) {
  FrameDrawer drawer(rasterizer);
  return drawer.Draw(mesh, light, env, camera, o, angle, view_scale);
}

ToneMapOptions FrameToneMap(const RenderOptions& o, double exposure_ev) {
  if (o.view == View::kTransport) return ToneMapOptions{};  // false colours pass through unchanged
  ToneMapOptions tone;
  tone.curve = o.tonemap;
  tone.exposure_ev = float(exposure_ev);
  return tone;
}

void FinishFrame(Image8& image, const RenderOptions& o, double view_scale) {
  if (o.view == View::kTransport) DrawDivergingLegend(image, view_scale, "T" + std::to_string(o.transport_index));
}

ToneMapped ToneMapFrame(const RasterImage& frame, const RenderOptions& o, double exposure_ev, double view_scale) {
  ToneMapped mapped = ToneMap(frame.image, FrameToneMap(o, exposure_ev));
  FinishFrame(mapped.image, o, view_scale);
  return mapped;
}

double TransportViewScale(const FrameLight& light, std::size_t vertices, int index) {
  CheckViewCoefficient(light, index);
  double scale = 0.0;
  for (std::size_t v = 0; v < vertices; ++v) scale = std::max(scale, std::abs(light.Coefficient(v, index)));
  return scale;
}

ToneMapped DrawFrame(Rasterizer& rasterizer, const Mesh& mesh, FrameLight& light, const Environment& env,
                     const Camera& camera, const RenderOptions& o, double angle, double exposure_ev) {
  const double scale = o.view == View::kTransport ? TransportViewScale(light, mesh.vertex_count(), o.transport_index) : 0.0;
  return ToneMapFrame(RasterizeFrame(rasterizer, mesh, light, env, camera, o, angle, scale), o, exposure_ev, scale);
}

FrameStats RenderFrames(const Mesh& mesh, FrameLight& light, const Environment& env, const Camera& camera,
                        const RenderOptions& o, OutputFolder& folder, VideoWriter* video) {
  FrameStats stats;
  Rasterizer rasterizer;
  const bool transport_view = o.view == View::kTransport;
  const double view_scale = transport_view ? TransportViewScale(light, mesh.vertex_count(), o.transport_index) : 0.0;
  stats.legend_left_out =
      transport_view && !LayoutDivergingLegend(o.width, o.height, view_scale, "T" + std::to_string(o.transport_index));
  // The automatic exposure is measured on frame 0 (its light at angle 0) and used for all frames.
  const bool measure = !o.exposure && !transport_view;
  stats.exposure = o.exposure.value_or(0.0);
  // Frames encoded and written on other threads, one frame per thread at most: the bytes of
  // each file do not depend on how many are in flight. Every buffer lives across frames.
  FrameWriter writer(ThreadCount(), video);
  FrameDrawer drawer;
  const Bounds3 bounds = MeshBounds(mesh);
  // The frames written: all, or --frame-range's. Frame 0 measures the exposure first, drawn and
  // not written when the range starts later.
  const int first = o.first_frame, last = o.last_frame < 0 ? o.frames - 1 : o.last_frame;
  stats.frames = last - first + 1;
  if (measure && first > 0) {
    Image8 unwritten;
    const RasterImage& frame0 = drawer.Draw(mesh, light, env, Orbit(camera, 0.0, bounds.lo, bounds.hi), o, FrameAngle(o, 0),
                                            view_scale, nullptr, &unwritten);
    stats.exposure = AutoExposureEv(frame0, o.tonemap);
  }
  Progress progress("rendering", static_cast<std::size_t>(stats.frames));
  for (int i = first; i <= last; ++i) {
    // Each frame from its absolute angle: no accumulated drift.
    const double angle = FrameAngle(o, i);
    Image8& image = writer.Next(i - first, &stats.encode_seconds);  // rethrows an earlier frame's write error
    const auto t0 = std::chrono::steady_clock::now();
    const Camera seen_from = Orbit(camera, o.orbit * double(i) / double(o.frames), bounds.lo, bounds.hi);
    // Frame 0 measures the exposure on the linear frame first; the others are tone mapped band
    // by band as they are drawn (raster/rasterizer.h), the same bytes.
    const bool measure_now = i == 0 && measure;
    const ToneMapOptions tone = FrameToneMap(o, stats.exposure);
    const RasterImage& frame = drawer.Draw(mesh, light, env, seen_from, o, angle, view_scale,
                                           measure_now ? nullptr : &tone, &image);
    ToneMapCounts counts = frame.tone_counts;
    if (measure_now) {
      stats.exposure = AutoExposureEv(frame, o.tonemap);
      counts = ToneMapInto(frame.image, FrameToneMap(o, stats.exposure), image);
    }
    FinishFrame(image, o, view_scale);
    stats.draw_seconds += SecondsSince(t0);
    stats.negative_pixels += counts.negative_pixels;
    stats.nan_pixels += counts.nan_pixels;
    writer.Submit(folder.Output(FrameName(i, o.frames)));
    progress.Advance(1);
  }
  stats.encode_seconds += writer.Finish();
  return stats;
}

}  // namespace prt
