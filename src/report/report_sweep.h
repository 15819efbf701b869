#pragma once
/// \file
/// The measurements behind `prt report`: PRT's per-vertex error against its run time.
///
/// For each transport mode, sampler (uniform, stratified, fibonacci) and directions per vertex
/// (doubling from `min_samples` to `max_samples`) the transport is computed once at `max_lmax`
/// and scored; its bands 0..L are exactly what a run at lmax L would compute with the same
/// directions (each coefficient is its own sum over the same rays), so every lmax L <= max_lmax
/// is evaluated from that one run, and its time and work are that run's (`timed_lmax`; the
/// report and its plot say so).
/// Each (mode, sampler, samples, lmax) is scored by
///   (a) sampling error: vertex radiance against the converged transport at the same lmax
///       (fibonacci, `converged_samples` directions), i.e. the Monte Carlo noise alone;
///   (b) total error: against the ground truth of precompute/reference.h, SH truncation
///       included;
///   and the PSNR of its picture against the reference picture (report/report_image.h).
/// Unshadowed transport is closed form: one row per lmax, truncation error only.
/// Times: after every configuration is scored, all of them (the sampled runs, the closed form
/// and the light projections) are timed together in round robin (round_robin_timing.h), each
/// as the median and range of at least 5 samples, and the work order is checked: twice the
/// rays (or texels) never faster beyond the spread. Work is counted beside the seconds: rays
/// traced and basis evaluations per run.
/// Light projection is measured separately: the sky averaged into cubemaps of growing face size,
/// projected (timed) and compared coefficient by coefficient with its exact projection.

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "basis/study.h"
#include "basis/timed_transport.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/error_metrics.h"
#include "precompute/transport.h"
#include "render/render_options.h"
#include "report/report_glossy.h"
#include "report/report_scene.h"
#include "report/report_noise.h"
#include "report/round_robin_timing.h"

namespace prt {

struct ReportConfig {
  std::vector<TransportMode> modes = {TransportMode::kShadowed, TransportMode::kInterreflection};
  int min_samples = 16, max_samples = 16384;
  int max_lmax = 8;
  int converged_samples = 65536;
  int reference_samples = 8192;
  int bounces = 1;
  std::uint64_t seed = 1;
  std::vector<int> face_sizes = {8, 16, 32, 64, 128, 256, 512};
  int image_width = 320, image_height = 240;
};

struct SweepRow {
  std::string mode, sampler;  ///< sampler "closed-form" for unshadowed
  int samples = 0;            ///< requested directions per vertex
  int directions = 0;         ///< actually used (stratified: floor(sqrt)^2)
  int lmax = 0;
  int timed_lmax = 0;         ///< lmax of the run timed: the sweep's max_lmax (its bands reused)
  TimingStats time;           ///< transport seconds of that run (round_robin_timing.h)
  std::uint64_t rays = 0;     ///< rays that run traced (0: closed form)
  std::uint64_t basis_evaluations = 0;  ///< directions whose basis it evaluated
  VertexError sampling, total;
  double psnr = 0;            ///< dB against the reference picture
};

struct ModeBaseline {
  std::string mode;
  double reference_seconds = 0, reference_rms_error = 0, reference_rms_radiance = 0;
  int reference_samples = 0;
  double converged_seconds = 0;
  int converged_samples = 0;
  /// Relative difference between converged and a half-sample-count run (an upper bound on the
  /// converged result's own noise), at max_lmax.
  double converged_self_error = 0;
  /// [l] for l = 0..max_lmax: the converged transport's total error at lmax l (relative RMS),
  /// i.e. the SH truncation error (plus the reference's own, much smaller, noise). Empty for
  /// unshadowed, whose rows hold it directly.
  std::vector<double> truncation;
};

/// One cubemap resolution of the light-projection study. Each texel holds the environment's
/// average over its solid angle (what a real, filtered cubemap stores), from sub-texel samples
/// weighted by their exact solid angles; a texel-centre sample instead lets the sky's small sun
/// fall between centres at some sizes and onto one at others, which made the error jump up and
/// down with the face size.
struct LightRow {
  int face_size = 0;
  int supersample = 1;         ///< sub-texel samples per side of each texel
  TimingStats time;            ///< ProjectLight on the cubemap (round robin with the sweep)
  double coeff_error = 0;      ///< relative L2 error of all coefficients (bands 0..max_lmax)
};

struct ReportData {
  std::string scene, environment;
  int vertices = 0;
  std::vector<SweepRow> rows;
  std::vector<ModeBaseline> baselines;
  std::vector<LightRow> light;
  int max_lmax = 0;
  double bvh_seconds = 0;  ///< BVH build inside each sampled run (the fastest seen): a fixed cost
  RoundRobinPlan timing;   ///< how the times were taken
  int timed_configurations = 0;
  std::vector<OrderViolation> order_violations;  ///< CheckWorkOrder of the sweep and the light rows
  std::optional<GlossyStudy> glossy;  ///< with --material phong:N,KS (report_glossy.h)
  std::optional<NoiseStudy> noise;    ///< the visible-noise study (report_noise.h)
  /// With --basis NAME whose basis has a study (Basis::Study, basis/study.h): its results, which
  /// the report writes as they are (report.csv rows, a report.md section, basis_error.png).
  std::shared_ptr<const StudyResults> basis_study;
};

/// Spread (TimingStats::Spread: interquartile range / median) of a configuration's times above
/// which the report calls its times noisy: it then says so at its top and fits no slope to
/// seconds. Measured with `prt report --quick` on this project's 2-core machine (AMD EPYC, 2
/// threads): the largest spread of three idle runs was 16, 17 and 21 %; of three runs beside two
/// busy processes (`yes > /dev/null` twice), 82, 82 and 980 %, their seconds 1.3 to 2.7 times the
/// idle ones. The order of the points held in all six.
inline constexpr double kTrustedSpread = 0.4;

/// Whether the sweep's times can carry slopes: no order violation and no spread above
/// kTrustedSpread among the sampled rows and light rows.
bool TimesTrusted(const ReportData& data);
/// The largest spread among the sampled rows and light rows, and whose it is.
std::pair<double, std::string> LargestSpread(const ReportData& data);

/// Runs the whole sweep (minutes for the defaults; progress on the run summary).
ReportData RunReportSweep(const Mesh& mesh, const Environment& env, const std::string& env_spec,
                          const ReportConfig& config, const RenderOptions& picture);

}  // namespace prt
