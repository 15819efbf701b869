#include "app/render_frames.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <regex>

#include <glm/matrix.hpp>

#include "core/error.h"
#include "core/progress.h"
#include "geometry/mesh_ops.h"
#include "io/png_io.h"
#include "precompute/shade.h"
#include "io/image_load.h"
#include "raster/annotate.h"
#include "raster/rasterizer.h"
#include "sh/basis.h"
#include "raster/tonemap.h"

namespace prt {
namespace fs = std::filesystem;
namespace {

constexpr double kPi = 3.14159265358979323846;

double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Frame files in `dir` numbered `first` or higher (left from an earlier, longer run).
std::size_t CountStaleFrames(const std::string& dir, int first) {
  static const std::regex pattern("frame_([0-9]+)\\.png");
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, m, pattern) && std::stoll(m[1].str()) >= first) ++n;
  }
  return n;
}

}  // namespace

std::string FrameName(int i) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame_%04d.png", i);
  return buf;
}

Camera ChooseCamera(const Mesh& mesh, const RenderOptions& o) {
  const Bounds3 b = MeshBounds(mesh);
  Camera c = FrameBounds(b.lo, b.hi, float(o.width) / float(o.height));
  if (o.eye) c.eye = glm::vec3(*o.eye);
  if (o.target) c.target = glm::vec3(*o.target);
  if (o.up) c.up = glm::vec3(*o.up);
  if (o.fov) c.fov_deg = float(*o.fov);
  c = FitClipPlanes(c, b.lo, b.hi);
  CheckCamera(c);
  return c;
}

namespace {

/// Radiance of the SH reconstruction sum_k L_k Y_k(d).
glm::vec3 Reconstruct(const ShRgb& light, const glm::dvec3& d) {
  const int lmax = LmaxOfCount(light.size());
  double y[CoeffCount(kMaxLmax)];
  EvalBasis(lmax, d, y);
  glm::dvec3 sum(0.0);
  for (std::size_t k = 0; k < light.size(); ++k) sum += y[k] * light[k];
  return glm::vec3(sum);
}

/// Per-vertex colours of the chosen view; `scale` receives max |T_K| for the transport view.
std::vector<glm::vec3> ViewColors(const Mesh& mesh, const Transport& transport, const ShRgb& lit,
                                  const RenderOptions& o, double& scale) {
  if (o.view == "irradiance") return ShadeVertices(mesh, transport, lit, false);
  if (o.view == "albedo") return mesh.albedo;
  std::vector<glm::vec3> colors(mesh.vertex_count());
  if (o.view == "light") {
    for (std::size_t v = 0; v < colors.size(); ++v) colors[v] = Reconstruct(lit, glm::dvec3(mesh.normals[v]));
    return colors;
  }
  if (o.view == "transport") {
    scale = 0.0;
    for (std::size_t v = 0; v < colors.size(); ++v) scale = std::max(scale, double(std::abs(transport.at(v, 0)[o.transport_index])));
    const double s = scale > 0 ? scale : 1.0;
    for (std::size_t v = 0; v < colors.size(); ++v) {
      // Palette colours are display values: decode them so the sRGB tone curve restores them.
      const glm::vec3 c = DivergingColor(transport.at(v, 0)[o.transport_index] / s);
      colors[v] = glm::vec3(SrgbToLinear(c.x), SrgbToLinear(c.y), SrgbToLinear(c.z));
    }
    return colors;
  }
  return ShadeVertices(mesh, transport, lit);
}

}  // namespace

ToneMapped DrawFrame(Rasterizer& rasterizer, const Mesh& mesh, const Transport& transport, const ShRgb& light,
                     const AxisRotation& rotation, const Environment& env, const Camera& camera,
                     const RenderOptions& o, double angle) {
  if (o.view == "transport" && o.transport_index >= CoeffCount(transport.lmax))
    throw UsageError("--view: transport:" + std::to_string(o.transport_index) + " is out of range (expected 0 to " +
                         std::to_string(CoeffCount(transport.lmax) - 1) + " for lmax " + std::to_string(transport.lmax) + ")",
                     "render");
  // The light, and the environment behind the mesh, turned by R: L'(d) = L(R^T d). Only the
  // bands the transport has are turned.
  const ShRgb used(light.begin(), light.begin() + std::min(light.size(), std::size_t(CoeffCount(transport.lmax))));
  const ShRgb lit = rotation.Rotate(used, angle);
  double scale = 0.0;
  const std::vector<glm::vec3> colors = ViewColors(mesh, transport, lit, o, scale);
  RasterOptions ro;
  ro.ssaa = o.ssaa;
  ro.background.color = o.background_color;
  if (o.view == "light") {
    ro.background.radiance = [&lit](const glm::vec3& d) { return Reconstruct(lit, glm::dvec3(d)); };
  } else if (o.env_background) {
    const glm::mat3 inverse(glm::transpose(AxisAngle(glm::normalize(o.axis), angle)));
    ro.background.radiance = [&env, inverse](const glm::vec3& d) { return glm::vec3(env.Radiance(glm::dvec3(inverse * d))); };
  }
  const RasterImage& frame = rasterizer.Draw(camera, o.width, o.height, mesh.positions, mesh.triangles, colors, ro);
  ToneMapOptions tone;
  tone.curve = o.tonemap;
  tone.exposure_ev = float(o.exposure);
  if (o.view == "transport") tone = ToneMapOptions{};  // false colours pass through unchanged
  ToneMapped mapped = ToneMap(frame.image, tone);
  if (o.view == "transport") DrawDivergingLegend(mapped.image, scale, "T" + std::to_string(o.transport_index));
  return mapped;
}

FrameStats RenderFrames(const Mesh& mesh, const Transport& transport, const ShRgb& light,
                        const Environment& env, const Camera& camera, const RenderOptions& o) {
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (!fs::is_directory(o.out)) throw Error(o.out + ": cannot create the output folder");

  FrameStats stats;
  stats.frames = o.frames;
  Rasterizer rasterizer;
  const AxisRotation rotation(o.axis, transport.lmax);
  std::future<void> writing;  // the previous frame's encode-and-write
  Progress progress("rendering", static_cast<std::size_t>(o.frames));
  for (int i = 0; i < o.frames; ++i) {
    // Each frame from its absolute angle: no accumulated drift.
    const double angle = 2.0 * kPi * o.turns * double(i) / double(o.frames);
    const auto t0 = std::chrono::steady_clock::now();
    ToneMapped mapped = DrawFrame(rasterizer, mesh, transport, light, rotation, env, camera, o, angle);
    stats.draw_seconds += Since(t0);
    stats.negative_pixels += mapped.negative_pixels;
    stats.nan_pixels += mapped.nan_pixels;

    const auto t1 = std::chrono::steady_clock::now();
    if (writing.valid()) writing.get();  // rethrows a write error
    stats.encode_seconds += Since(t1);
    const std::string path = o.out + "/" + FrameName(i);
    writing = std::async(std::launch::async, [path, image = std::move(mapped.image)] { WritePng(path, image); });
    progress.Advance(1);
  }
  const auto t1 = std::chrono::steady_clock::now();
  if (writing.valid()) writing.get();
  stats.encode_seconds += Since(t1);
  stats.stale_frames = CountStaleFrames(o.out, o.frames);
  return stats;
}

}  // namespace prt
