#include "report/report_noise.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/log.h"
#include "core/text.h"
#include "precompute/light.h"
#include "precompute/sample_rule.h"
#include "precompute/shade.h"
#include "raster/exposure.h"
#include "core/markdown_table.h"
#include "render/render_frames.h"
#include "render/seen_vertices.h"
#include "sh_basis/frame_light.h"

namespace prt {

std::vector<NoiseMethod> NoiseMethods(int lmax) {
  const Sampler s = Sampler::kFibonacci;
  return {
      {"one set per vertex from a pool of 64, 1024 directions (the default before)", 1024, 1024, 64},
      {"one set shared by every vertex, 1024 directions", 1024, 1024, 1},
      {"one set per vertex, 4096 directions", 4096, 4096, 64},
      {"the sample rule's default: " + std::to_string(DefaultSamples(lmax, s)) + " for the vertices the camera sees, " +
           std::to_string(DefaultHiddenSamples(lmax, s)) + " for the others",
       DefaultSamples(lmax, s), DefaultHiddenSamples(lmax, s), 64},
      {"one set per vertex, 16384 directions", 16384, 16384, 64},
  };
}

Image8 NoiseFrame(const Mesh& mesh, const Transport& transport, const ShRgb& light, const Environment& env,
                  const RenderOptions& picture, std::optional<double>& ev) {
  Rasterizer rasterizer;
  const Camera camera = ChooseCamera(mesh, picture);
  const auto sh = MakeShFrameLight(transport, light, picture.axis);
  const RasterImage& frame = RasterizeFrame(rasterizer, mesh, *sh, env, camera, picture, 0.0, 1.0);
  if (!ev) ev = AutoExposureEv(frame, picture.tonemap);
  return ToneMapFrame(frame, picture, *ev, 1.0).image;
}

namespace {

TransportOptions OptionsOf(const NoiseConfig& c, const NoiseMethod& m, const std::vector<std::uint8_t>& seen) {
  TransportOptions o;
  o.mode = c.mode;
  o.lmax = c.lmax;
  o.samples = m.samples;
  o.hidden_samples = m.hidden_samples;
  o.direction_sets = m.direction_sets;
  o.seed = c.seed;
  o.bounces = c.bounces;
  o.seen = seen;  // used only where the two counts differ
  return o;
}

double PixelShare(std::size_t count, std::size_t pixels) { return pixels ? double(count) / double(pixels) : 0.0; }

/// Relative RMS of the seen vertices' radiance (albedo 1, the three channels summed) against
/// the converged transport's.
double SeenRmsError(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b,
                    const std::vector<std::uint8_t>& seen) {
  double num = 0.0, den = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v) {
    if (!seen[v]) continue;
    const double x = a[v].x + a[v].y + a[v].z, y = b[v].x + b[v].y + b[v].z;
    num += (x - y) * (x - y);
    den += y * y;
  }
  return den > 0.0 ? std::sqrt(num / den) : 0.0;
}

}  // namespace

NoiseStudy RunNoiseStudy(const Mesh& mesh, const Environment& env, const NoiseConfig& config,
                         const RenderOptions& picture) {
  NoiseStudy study;
  study.config = config;
  study.vertices = mesh.vertex_count();
  const ShRgb light = ProjectLight(env, config.lmax);
  const Camera camera = ChooseCamera(mesh, picture);
  const std::vector<std::uint8_t> seen = SeenVertices(mesh, camera, picture);
  for (std::uint8_t s : seen) study.seen_vertices += s;

  const NoiseMethod converged{"converged", config.converged_samples, config.converged_samples, 64};
  const Transport truth = ComputeTransport(mesh, OptionsOf(config, converged, seen), nullptr);
  std::optional<double> exposure;
  const Image8 truth_frame = NoiseFrame(mesh, truth, light, env, picture, exposure);
  study.exposure = *exposure;
  study.pixels = std::size_t(truth_frame.width) * std::size_t(truth_frame.height);
  const std::vector<glm::vec3> truth_radiance = ShadeVertices(mesh, truth, light, false);

  // Only methods well below the converged count: a method at the converged count would be
  // compared with itself.
  std::vector<NoiseMethod> methods;
  for (const NoiseMethod& m : NoiseMethods(config.lmax))
    if (4 * m.samples <= config.converged_samples) methods.push_back(m);
  std::vector<std::vector<double>> seconds(methods.size());
  study.rows.resize(methods.size());
  // Repeats interleaved across the methods, so that a change of the machine's speed during the
  // study touches every method alike.
  for (int repeat = 0; repeat < std::max(1, config.repeats); ++repeat) {
    for (std::size_t m = 0; m < methods.size(); ++m) {
      TransportReport r;
      const auto t0 = std::chrono::steady_clock::now();
      const Transport t = ComputeTransport(mesh, OptionsOf(config, methods[m], seen), &r);
      seconds[m].push_back(SecondsSince(t0));
      if (repeat > 0) continue;
      NoiseRow& row = study.rows[m];
      row.method = methods[m];
      row.rays = r.rays;
      row.rms_error = SeenRmsError(ShadeVertices(mesh, t, light, false), truth_radiance, seen);
      row.frame = CompareImages(NoiseFrame(mesh, t, light, env, picture, exposure), truth_frame);
    }
  }
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::sort(seconds[m].begin(), seconds[m].end());
    study.rows[m].seconds = seconds[m][seconds[m].size() / 2];
  }
  return study;
}

std::string NoiseMarkdown(const NoiseStudy& s) {
  std::string md = "## Visible noise\n\n";
  md += Formatted(
      "Frame 0 (%s transport, lmax %d, the render's camera, tone curve and supersampling, exposure %.1f EV "
      "measured on the converged frame) of each way of spending directions, against the same frame with %d "
      "directions at every vertex: the largest per-pixel difference in 8-bit levels and the share of pixels "
      "more than one level apart (what a viewer sees as blotches), the relative RMS error of the radiance of the "
      "%zu of %zu vertices the camera sees, the rays traced and the transport's time (median of %d runs, "
      "interleaved).\n\n",
      TransportModeName(s.config.mode), s.config.lmax, s.exposure, s.config.converged_samples, s.seen_vertices,
      s.vertices, s.config.repeats);
  const MarkdownAlign right = MarkdownAlign::kRight;
  md += MarkdownHeader({"method", "largest difference (levels)", "pixels > 1 level", "RMS error (seen vertices)", "rays",
                        "seconds"},
                       {MarkdownAlign::kDefault, right, right, right, right, right});
  for (const NoiseRow& r : s.rows)
    md += MarkdownRow({r.method.name, std::to_string(r.frame.max_abs),
                       Formatted("%.3f%%", 100.0 * PixelShare(r.frame.pixels_over_one, s.pixels)),
                       Formatted("%.3f%%", 100.0 * r.rms_error), std::to_string(r.rays), Formatted("%.3f", r.seconds)});
  return md + "\n";
}

}  // namespace prt
