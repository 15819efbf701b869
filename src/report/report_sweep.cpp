#include "report/report_sweep.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <limits>

#include "core/log.h"
#include "core/text.h"
#include "env/cubemap.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "precompute/light.h"
#include "precompute/reference.h"
#include "precompute/shade.h"
#include "raster/image_diff.h"
#include "render/render_frames.h"
#include "report/report_image.h"

namespace prt {
namespace {

using Clock = std::chrono::steady_clock;

double RelativeL2(const ShRgb& x, const ShRgb& ref) {
  double d2 = 0, r2 = 0;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    const glm::dvec3 d = x[k] - ref[k];
    d2 += glm::dot(d, d);
    r2 += glm::dot(ref[k], ref[k]);
  }
  return r2 > 0 ? std::sqrt(d2 / r2) : std::sqrt(d2);
}

struct Scorer {
  const Mesh& mesh;
  const Environment& env;
  const Camera& camera;
  const RenderOptions& picture;
  const ShRgb& light;
  const Reference& reference;
  const Image8& reference_image;

  /// Scores the transport `t` (of max lmax) at every lmax against the converged transport.
  void Score(const Transport& t, const Transport* converged, SweepRow row, int max_lmax,
             std::vector<SweepRow>& rows) const {
    for (int l = 1; l <= max_lmax; ++l) {
      // ShadeVertices uses as many bands as the light has: the transport's first l bands.
      const std::vector<glm::vec3> colors = ShadeVertices(mesh, t, FirstBands(light, l));
      row.lmax = l;
      if (converged)
        row.sampling = CompareVertices(colors, ShadeVertices(mesh, *converged, FirstBands(light, l)));
      row.total = CompareVertices(colors, reference.radiance);
      row.psnr = CompareImages(DrawVertexColors(mesh, colors, env, camera, picture), reference_image).psnr;
      rows.push_back(row);
    }
  }
};

/// Sub-texels per side for the light study's cubemap of face `size`: fine enough that the
/// sub-texels are 1/kFineFaceSize of a face wide (0.09 degrees, against the default sun's
/// radius of 2 degrees), so every face size sees the same sun; at least 2.
constexpr int kFineFaceSize = 1024;
int LightSupersample(int size) { return std::max(2, (kFineFaceSize + size - 1) / size); }

}  // namespace

bool TimesTrusted(const ReportData& d) {
  return d.order_violations.empty() && LargestSpread(d).first <= kTrustedSpread;
}

std::pair<double, std::string> LargestSpread(const ReportData& d) {
  std::pair<double, std::string> worst{0.0, ""};
  for (const SweepRow& r : d.rows)
    if (r.sampler != "closed-form" && r.lmax == r.timed_lmax && r.time.Spread() > worst.first)
      worst = {r.time.Spread(), r.mode + " " + r.sampler + " " + std::to_string(r.directions) + " directions"};
  for (const LightRow& l : d.light)
    if (l.time.Spread() > worst.first) worst = {l.time.Spread(), "light projection, face " + std::to_string(l.face_size)};
  return worst;
}

ReportData RunReportSweep(const Mesh& mesh, const Environment& env, const std::string& env_spec,
                          const ReportConfig& c, const RenderOptions& picture) {
  ReportData data;
  data.environment = env_spec;
  data.vertices = static_cast<int>(mesh.vertex_count());
  data.max_lmax = c.max_lmax;
  const ShRgb light = ProjectLight(env, c.max_lmax);
  const Camera camera = ChooseCamera(mesh, picture);
  // What the round robin times at the end: one run of each configuration, and the rows (first,
  // count) of data.rows its time goes to.
  struct Job {
    std::function<void()> run;
    std::size_t first = 0, count = 0;
  };
  std::vector<Job> jobs;
  const auto scored = [&](const TransportOptions& o, SweepRow row, const Transport* converged, const Scorer& scorer) {
    TransportReport r;
    const Transport t = ComputeTransport(mesh, o, &r);
    row.directions = r.directions_per_vertex;
    row.rays = r.rays;
    row.basis_evaluations = r.basis_evaluations;
    row.timed_lmax = c.max_lmax;
    if (r.bvh_built) data.bvh_seconds = data.bvh_seconds > 0 ? std::min(data.bvh_seconds, r.bvh_seconds) : r.bvh_seconds;
    const std::size_t first = data.rows.size();
    scorer.Score(t, converged, row, c.max_lmax, data.rows);
    jobs.push_back({[&mesh, o] { ComputeTransport(mesh, o, nullptr); }, first, data.rows.size() - first});
  };

  std::vector<TransportMode> modes = {TransportMode::kUnshadowed};
  for (TransportMode m : c.modes)
    if (m != TransportMode::kUnshadowed) modes.push_back(m);
  for (TransportMode mode : modes) {
    ModeBaseline base;
    base.mode = TransportModeName(mode);
    // Ground truth of this mode.
    ReferenceOptions ro;
    ro.mode = mode;
    ro.samples = c.reference_samples;
    ro.bounces = c.bounces;
    ro.seed = c.seed + 1000;
    auto t0 = Clock::now();
    const Reference reference = ComputeReference(mesh, env, ro);
    base.reference_seconds = SecondsSince(t0);
    base.reference_rms_error = reference.rms_error;
    base.reference_rms_radiance = reference.rms_radiance;
    base.reference_samples = c.reference_samples;
    const Image8 reference_image = DrawVertexColors(mesh, ToFloat(reference.radiance), env, camera, picture);
    const Scorer scorer{mesh, env, camera, picture, light, reference, reference_image};
    char line[256];
    std::snprintf(line, sizeof line, "report: %s reference, %d directions per vertex [%.2f s], own RMS error %.3g%%",
                  base.mode.c_str(), c.reference_samples, base.reference_seconds,
                  100.0 * reference.rms_error / std::max(reference.rms_radiance, 1e-300));
    Summary(line);

    TransportOptions to;
    to.mode = mode;
    to.lmax = c.max_lmax;
    to.bounces = c.bounces;
    to.seed = c.seed;
    if (mode == TransportMode::kUnshadowed) {
      SweepRow row;
      row.mode = base.mode;
      row.sampler = "closed-form";
      scored(to, row, nullptr, scorer);
      data.baselines.push_back(base);
      continue;
    }
    // The converged transport, and a half-size run to bound its own noise: one run each.
    to.sampler = Sampler::kFibonacci;
    to.samples = c.converged_samples;
    t0 = Clock::now();
    const Transport converged = ComputeTransport(mesh, to, nullptr);
    base.converged_seconds = SecondsSince(t0);
    base.converged_samples = c.converged_samples;
    to.samples = c.converged_samples / 2;
    to.seed = c.seed + 7;
    const Transport half = ComputeTransport(mesh, to, nullptr);
    base.converged_self_error =
        CompareVertices(ShadeVertices(mesh, half, light), ShadeVertices(mesh, converged, light)).relative;
    to.seed = c.seed;
    base.truncation.assign(c.max_lmax + 1, 0.0);
    for (int l = 0; l <= c.max_lmax; ++l)
      base.truncation[l] = CompareVertices(ShadeVertices(mesh, converged, FirstBands(light, l)), reference.radiance).relative;
    std::snprintf(line, sizeof line, "report: %s converged transport, %d fibonacci directions [%.2f s]",
                  base.mode.c_str(), c.converged_samples, base.converged_seconds);
    Summary(line);
    data.baselines.push_back(base);

    for (Sampler s : {Sampler::kUniform, Sampler::kStratified, Sampler::kFibonacci}) {
      for (int n = c.min_samples; n <= c.max_samples; n *= 2) {
        to.sampler = s;
        to.samples = n;
        SweepRow row;
        row.mode = base.mode;
        row.sampler = SamplerName(s);
        row.samples = n;
        scored(to, row, &converged, scorer);
      }
      Summary("report: " + base.mode + " " + SamplerName(s) + " swept");
    }
  }

  // Light projection against cubemap resolution: the cubemaps built first, their projection
  // timed with the rest.
  std::vector<std::shared_ptr<const Environment>> cubes;
  for (int size : c.face_sizes) {
    LightRow row;
    row.face_size = size;
    row.supersample = LightSupersample(size);
    cubes.push_back(CubemapFromFunction([&env](const glm::dvec3& d) { return env.Radiance(d); }, size,
                                        CubeLayout::kStandard, row.supersample));
    row.coeff_error = RelativeL2(ProjectLight(*cubes.back(), c.max_lmax), light);
    data.light.push_back(row);
  }

  // Every configuration timed together, interleaved (round_robin_timing.h).
  std::vector<std::function<void()>> runs;
  for (const Job& j : jobs) runs.push_back(j.run);
  for (const auto& cube : cubes) runs.push_back([&cube, &c] { ProjectLight(*cube, c.max_lmax); });
  data.timed_configurations = static_cast<int>(runs.size());
  Summary("report: timing " + std::to_string(runs.size()) + " configurations in round robin, at least " +
          std::to_string(data.timing.min_rounds) + " rounds");
  const auto timing_start = Clock::now();
  const std::vector<TimingStats> times = TimeRoundRobin(runs, data.timing);
  const double timing_seconds = SecondsSince(timing_start);
  std::vector<TimedWork> order;
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    for (std::size_t k = 0; k < jobs[j].count; ++k) data.rows[jobs[j].first + k].time = times[j];
    const SweepRow& r = data.rows[jobs[j].first];
    if (r.sampler != "closed-form")
      order.push_back({r.mode + " " + r.sampler, std::to_string(r.directions) + " directions", double(r.rays), times[j]});
  }
  for (std::size_t i = 0; i < data.light.size(); ++i) {
    LightRow& l = data.light[i];
    l.time = times[jobs.size() + i];
    order.push_back({"light projection", "face " + std::to_string(l.face_size), 6.0 * l.face_size * l.face_size, l.time});
  }
  data.order_violations = CheckWorkOrder(order);
  const auto [spread, whose] = LargestSpread(data);
  Summary("report: timed in " + std::to_string(times.empty() ? 0 : times[0].samples) + " rounds" +
          Formatted(" [%.2f s]", timing_seconds) + "; largest spread " +
          Formatted("%.0f%%", 100.0 * spread) + (whose.empty() ? "" : " (" + whose + ")") + "; " +
          (data.order_violations.empty() ? std::string("time grows with work")
                                         : std::to_string(data.order_violations.size()) + " pairs out of work order"));
  return data;
}

}  // namespace prt
