#include "report/report_sweep.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/log.h"
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

Mesh MakeReportScene() {
  Mesh knot = MakeTorusKnot(2, 3, 0.16f, 128, 16, glm::vec3(0.80f, 0.38f, 0.20f));
  StandUpright(knot, 3.4f);
  Mesh scene = MakePlane(12.0f, 24, 0.0f, glm::vec3(0.7f, 0.7f, 0.7f));
  AppendMesh(scene, knot);
  return scene;
}

Transport TimedTransport(const Mesh& mesh, const TransportOptions& o, double& seconds, int& directions,
                         double* bvh_seconds) {
  Transport t;
  double total = 0.0;
  seconds = std::numeric_limits<double>::infinity();
  for (int repeat = 0; repeat < kMaxTimedRepeats && total < kMinTimedSeconds; ++repeat) {
    TransportReport r;
    const auto t0 = Clock::now();
    t = ComputeTransport(mesh, o, &r);
    const double run = SecondsSince(t0);
    total += run;
    if (run < seconds) {
      seconds = run;
      if (bvh_seconds) *bvh_seconds = r.bvh_seconds;
    }
    directions = r.directions_per_vertex;
  }
  return t;
}

ReportData RunReportSweep(const Mesh& mesh, const Environment& env, const std::string& env_spec,
                          const ReportConfig& c, const RenderOptions& picture) {
  ReportData data;
  data.environment = env_spec;
  data.vertices = static_cast<int>(mesh.vertex_count());
  data.max_lmax = c.max_lmax;
  const ShRgb light = ProjectLight(env, c.max_lmax);
  const Camera camera = ChooseCamera(mesh, picture);

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
      const Transport t = TimedTransport(mesh, to, row.seconds, row.directions);
      scorer.Score(t, nullptr, row, c.max_lmax, data.rows);
      data.baselines.push_back(base);
      continue;
    }
    // The converged transport, and a half-size run to bound its own noise.
    to.sampler = Sampler::kFibonacci;
    to.samples = c.converged_samples;
    int dirs = 0;
    const Transport converged = TimedTransport(mesh, to, base.converged_seconds, dirs);
    base.converged_samples = c.converged_samples;
    to.samples = c.converged_samples / 2;
    to.seed = c.seed + 7;
    double half_seconds = 0;
    const Transport half = TimedTransport(mesh, to, half_seconds, dirs);
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
        double bvh = 0.0;
        const Transport t = TimedTransport(mesh, to, row.seconds, row.directions, &bvh);
        data.bvh_seconds = data.bvh_seconds > 0 ? std::min(data.bvh_seconds, bvh) : bvh;
        scorer.Score(t, &converged, row, c.max_lmax, data.rows);
      }
      Summary("report: " + base.mode + " " + SamplerName(s) + " swept");
    }
  }

  // Light projection against cubemap resolution.
  for (int size : c.face_sizes) {
    LightRow row;
    row.face_size = size;
    row.supersample = LightSupersample(size);
    const auto cube = CubemapFromFunction([&env](const glm::dvec3& d) { return env.Radiance(d); }, size,
                                          CubeLayout::kStandard, row.supersample);
    const auto t0 = Clock::now();
    const ShRgb projected = ProjectLight(*cube, c.max_lmax);
    row.seconds = SecondsSince(t0);
    row.coeff_error = RelativeL2(projected, light);
    data.light.push_back(row);
  }
  return data;
}

}  // namespace prt
